#include <deal.II/base/bounding_box.h>
#include <deal.II/base/exceptions.h>

#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/fractures/segment_distance.h>

#include <cmath>
#include <iomanip>
#include <optional>
#include <ostream>
#include <sstream>

namespace PolyFrac
{
  namespace
  {
    template <int dim>
    std::string
    describe(const Fracture<dim> &fracture)
    {
      std::ostringstream out;
      for (unsigned int i = 0; i < fracture.points.size(); ++i)
        out << (i == 0 ? "" : " : ") << fracture.points[i];
      return out.str();
    }

    /** Throws naming the polygon unless it is convex and simple. */
    void
    check_convex(const Fracture<3> &fracture)
    {
      const auto &points = fracture.points;
      const auto &normal = fracture.normal;
      // Convex and simple: every turn is to the left about n^+ and the turns
      // add up to one full turn (a star polygon turns twice).
      const unsigned int n     = points.size();
      double             turns = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          const Tensor<1, 3> in  = points[i] - points[(i + n - 1) % n];
          const Tensor<1, 3> out = points[(i + 1) % n] - points[i];
          const double       sine =
            cross_product_3d(in, out) * normal / (in.norm() * out.norm());
          AssertThrow(sine >= -1e-10 && in.norm() > 0,
                      ExcMessage("The fracture polygon " + describe(fracture) +
                                 " is not convex (at its vertex " +
                                 std::to_string(i + 1) +
                                 "): PolyFrac takes planar convex polygons, "
                                 "their vertices in order around the boundary; "
                                 "split it into convex polygons."));
          turns += std::atan2(sine, in * out / (in.norm() * out.norm()));
        }
      AssertThrow(std::abs(turns - 2 * numbers::PI) < 1e-6,
                  ExcMessage("The fracture polygon " + describe(fracture) +
                             " crosses itself: give its vertices in order "
                             "around the boundary of a convex polygon."));
    }
  } // namespace



  template <int dim>
  Fracture<dim>::Fracture(const std::vector<Point<dim>> &points)
    : points(points)
  {
    if constexpr (dim == 2)
      {
        const Tensor<1, 2> ab = points[1] - points[0];
        measure               = ab.norm();
        AssertThrow(measure > 0,
                    ExcMessage("A fracture segment has length 0."));
        tangents[0] = ab / measure;
        normal[0]   = -tangents[0][1];
        normal[1]   = tangents[0][0];
      }
    else
      {
        Tensor<1, 3> newell;
        for (unsigned int i = 0; i < points.size(); ++i)
          newell +=
            0.5 * cross_product_3d(points[i] - points[0],
                                   points[(i + 1) % points.size()] - points[0]);
        measure = newell.norm();
        AssertThrow(measure > 0,
                    ExcMessage("A fracture polygon has zero area: " +
                               describe(*this)));
        normal = newell / measure;
        for (const Point<3> &p : points)
          AssertThrow(std::abs((p - points[0]) * normal) <=
                        1e-10 * std::sqrt(measure),
                      ExcMessage("The fracture polygon " + describe(*this) +
                                 " is not planar."));
        check_convex(*this);
        Tensor<1, 3> t = points[1] - points[0];
        t -= (t * normal) * normal;
        tangents[0] = t / t.norm();
        tangents[1] = cross_product_3d(normal, tangents[0]);
      }
  }



  template <int dim>
  double
  Fracture<dim>::distance(const Point<dim> &p) const
  {
    if constexpr (dim == 2)
      return distance_to_segment(p, points[0], points[1]);
    else
      {
        // Convex polygon: distance to the plane if the projection is
        // inside, else to the nearest edge.
        const double   height    = (p - points[0]) * normal;
        const Point<3> projected = p - height * normal;
        bool           inside    = true;
        for (unsigned int i = 0; i < points.size(); ++i)
          {
            const Tensor<1, 3> edge =
              points[(i + 1) % points.size()] - points[i];
            if (cross_product_3d(normal, edge) * (projected - points[i]) < 0)
              inside = false;
          }
        if (inside)
          return std::abs(height);
        double d = std::numeric_limits<double>::max();
        for (unsigned int i = 0; i < points.size(); ++i)
          d = std::min(d,
                       distance_to_segment(p,
                                           points[i],
                                           points[(i + 1) % points.size()]));
        return d;
      }
  }



  template <int dim>
  bool
  Fracture<dim>::on_boundary(const Point<dim> &p, const double tol) const
  {
    if constexpr (dim == 2)
      return p.distance(points[0]) <= tol || p.distance(points[1]) <= tol;
    else
      {
        for (unsigned int i = 0; i < points.size(); ++i)
          if (distance_to_segment(p,
                                  points[i],
                                  points[(i + 1) % points.size()]) <= tol)
            return true;
        return false;
      }
  }



  template <int dim>
  FractureNetwork<dim>::FractureNetwork(
    const std::vector<Fracture<dim>> &fractures,
    const MeshGeometry<dim>          &geometry)
    : fractures(fractures)
    , geometry(geometry)
    , fracture_face_index(geometry.mesh.n_faces(),
                          numbers::invalid_unsigned_int)
  {
    for (const Fracture<dim> &fracture : fractures)
      names.push_back(describe(fracture));
    const auto &mesh = geometry.mesh;
    for (unsigned int f = 0; f < mesh.n_faces(); ++f)
      {
        if (mesh.faces[f].at_boundary())
          continue;
        const double                tol = 1e-10 * geometry.faces[f].diameter;
        std::optional<unsigned int> found;
        for (unsigned int i = 0; i < fractures.size(); ++i)
          {
            bool on_fracture = true;
            for (const unsigned int v : mesh.faces[f].vertices)
              if (fractures[i].distance(mesh.vertices[v]) > tol)
                {
                  on_fracture = false;
                  break;
                }
            if (!on_fracture)
              continue;
            if (found)
              {
                std::ostringstream where;
                where << geometry.faces[f].centroid;
                AssertThrow(false,
                            ExcMessage(
                              "Fractures " + std::to_string(*found) + " (" +
                              names[*found] + ") and " + std::to_string(i) +
                              " (" + names[i] +
                              ") overlap: both contain the mesh face centred "
                              "at " +
                              where.str() +
                              ". Remove the duplicate, or shorten one so that "
                              "fractures meet only at " +
                              (dim == 2 ? "a point." : "a line.")));
              }
            found = i;
          }
        if (found)
          add_face(f, *found, fractures[*found].normal);
      }
    check_resolution();
  }



  template <int dim>
  FractureNetwork<dim>::FractureNetwork(
    const std::vector<std::string> &names,
    const std::vector<TaggedFace>  &tagged_faces,
    const MeshGeometry<dim>        &geometry)
    : names(names)
    , geometry(geometry)
    , fracture_face_index(geometry.mesh.n_faces(),
                          numbers::invalid_unsigned_int)
  {
    for (const TaggedFace &tagged : tagged_faces)
      {
        AssertThrow(!geometry.mesh.faces[tagged.face].at_boundary(),
                    ExcMessage("The fracture element of " +
                               names[tagged.fracture] +
                               " lies on the boundary of the domain."));
        add_face(tagged.face, tagged.fracture, tagged.normal);
      }
  }



  template <int dim>
  void
  FractureNetwork<dim>::add_face(const unsigned int    face,
                                 const unsigned int    fracture,
                                 const Tensor<1, dim> &normal)
  {
    const auto  &cells = geometry.mesh.faces[face].cells;
    const double side  = geometry.faces[face].normal * normal;
    AssertThrow(std::abs(side) > 0.5,
                ExcMessage(
                  "A fracture face is not aligned with its fracture."));
    fracture_face_index[face] = fracture_faces.size();
    fracture_faces.push_back({face,
                              fracture,
                              side > 0 ? cells[0] : cells[1],
                              side > 0 ? cells[1] : cells[0],
                              normal});
  }



  template <int dim>
  void
  FractureNetwork<dim>::check_resolution() const
  {
    const auto         &mesh = geometry.mesh;
    std::vector<double> covered(fractures.size(), 0.);
    for (const FractureFace &ff : fracture_faces)
      covered[ff.fracture] += geometry.faces[ff.face].measure;
    // The same measure over the boundary faces that lie on each fracture.
    std::vector<double> on_boundary(fractures.size(), 0.);
    for (unsigned int f = 0; f < mesh.n_faces(); ++f)
      if (mesh.faces[f].at_boundary())
        for (unsigned int i = 0; i < fractures.size(); ++i)
          {
            const double tol         = 1e-10 * geometry.faces[f].diameter;
            bool         on_fracture = true;
            for (const unsigned int v : mesh.faces[f].vertices)
              on_fracture =
                on_fracture && fractures[i].distance(mesh.vertices[v]) <= tol;
            if (on_fracture)
              on_boundary[i] += geometry.faces[f].measure;
          }
    const BoundingBox<dim> box(mesh.vertices);
    for (unsigned int i = 0; i < fractures.size(); ++i)
      {
        const std::string fracture =
          "Fracture " + std::to_string(i) + " (" + names[i] + ")";
        for (const Point<dim> &p : fractures[i].points)
          {
            std::ostringstream where;
            where << "(" << p << ") lies outside the mesh, whose bounding "
                  << "box runs from (" << box.get_boundary_points().first
                  << ") to (" << box.get_boundary_points().second << ")";
            AssertThrow(box.point_inside(p, 1e-10),
                        ExcMessage(fracture + ": its point " + where.str() +
                                   ". A fracture must lie inside the domain: "
                                   "move or shorten it."));
          }
        AssertThrow(on_boundary[i] < 1e-8 * fractures[i].measure,
                    ExcMessage(fracture +
                               " lies on the boundary of the domain, where it "
                               "would be a boundary, not a fracture: move it "
                               "inside, or give that boundary its own "
                               "boundary condition."));
        const double       fraction = covered[i] / fractures[i].measure;
        std::ostringstream percent;
        percent << 100 * fraction;
        AssertThrow(std::abs(fraction - 1) < 1e-8,
                    ExcMessage(
                      fracture +
                      " is not resolved by the mesh: its mesh faces cover " +
                      percent.str() +
                      " % of it. Choose a mesh whose faces lie on the fracture "
                      "(e.g. adapt Mesh/Subdivisions or the corners; on a "
                      "simplex box the faces are the diagonals of the "
                      "subdivisions)."));
      }
  }



  template <int dim>
  void
  FractureNetwork<dim>::print(std::ostream &out) const
  {
    std::vector<unsigned int>   n_faces(names.size(), 0);
    std::vector<Tensor<1, dim>> normals(names.size());
    for (const FractureFace &ff : fracture_faces)
      {
        ++n_faces[ff.fracture];
        normals[ff.fracture] = ff.normal;
      }
    for (unsigned int i = 0; i < names.size(); ++i)
      {
        out << "Fracture " << i << ": " << names[i] << "; n+ =";
        for (unsigned int d = 0; d < dim; ++d)
          out << ' ' << (std::abs(normals[i][d]) < 1e-12 ? 0. : normals[i][d]);
        out << "; " << n_faces[i] << " faces" << std::endl;
      }
  }



  template <int dim>
  Tensor<2, dim>
  FractureNetwork<dim>::frame(const unsigned int i) const
  {
    const Tensor<1, dim> n = normal(i);
    Tensor<2, dim>       Q;
    Q[0] = n;
    if constexpr (dim == 2)
      {
        // τ = (B − A)/|B − A| for n^+ = left normal of A -> B.
        Q[1][0] = n[1];
        Q[1][1] = -n[0];
      }
    else
      {
        const auto  &ff = fracture_faces[i];
        Tensor<1, 3> t  = fractures.empty() ? Tensor<1, 3>() :
                                              fractures[ff.fracture].tangents[0];
        if (t.norm() < 0.5)
          {
            // Tagged fractures: any unit vector orthogonal to n.
            t[std::abs(n[0]) < 0.9 ? 0 : 1] = 1;
            t -= (t * n) * n;
            t /= t.norm();
          }
        Q[1] = t;
        Q[2] = cross_product_3d(n, t);
      }
    return Q;
  }



  template struct Fracture<2>;
  template struct Fracture<3>;
  template <int dim>
  FaceSites<dim>
  FractureNetwork<dim>::face_sites(const MeshGeometry<dim> &geometry) const
  {
    FaceSites<dim> sites;
    for (const FractureFace &fracture_face : fracture_faces)
      {
        sites.centroids.push_back(geometry.faces[fracture_face.face].centroid);
        sites.fractures.push_back(fracture_face.fracture);
      }
    sites.n_fractures = n_fractures();
    return sites;
  }



  template class FractureNetwork<2>;
  template class FractureNetwork<3>;
} // namespace PolyFrac
