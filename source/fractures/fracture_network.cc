#include <deal.II/base/exceptions.h>

#include <polyfrac/fractures/fracture_network.h>

#include <iomanip>
#include <ostream>
#include <sstream>

namespace PolyFrac
{
  namespace
  {
    template <int dim>
    double
    distance_to_segment(const Point<dim> &p,
                        const Point<dim> &a,
                        const Point<dim> &b)
    {
      const Tensor<1, dim> ab = b - a;
      const double t = std::clamp((p - a) * ab / ab.norm_square(), 0., 1.);
      return p.distance(a + t * ab);
    }

    template <int dim>
    std::string
    describe(const Fracture<dim> &fracture)
    {
      std::ostringstream out;
      for (unsigned int i = 0; i < fracture.points.size(); ++i)
        out << (i == 0 ? "" : " : ") << fracture.points[i];
      return out.str();
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
        const double tol = 1e-10 * geometry.faces[f].diameter;
        for (unsigned int i = 0; i < fractures.size(); ++i)
          {
            bool on_fracture = true;
            for (const unsigned int v : mesh.faces[f].vertices)
              if (fractures[i].distance(mesh.vertices[v]) > tol)
                {
                  on_fracture = false;
                  break;
                }
            if (on_fracture)
              {
                add_face(f, i, fractures[i].normal);
                break;
              }
          }
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
    std::vector<double> covered(fractures.size(), 0.);
    for (const FractureFace &ff : fracture_faces)
      covered[ff.fracture] += geometry.faces[ff.face].measure;
    for (unsigned int i = 0; i < fractures.size(); ++i)
      {
        const double fraction = covered[i] / fractures[i].measure;
        AssertThrow(std::abs(fraction - 1) < 1e-8,
                    ExcMessage(
                      "Fracture " + std::to_string(i) + " (" + names[i] +
                      ") is not resolved by the mesh: its mesh faces cover " +
                      std::to_string(100 * fraction) +
                      " % of it. Choose a mesh whose faces lie on the fracture "
                      "(e.g. adapt Mesh/Subdivisions or the corners)."));
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
  template class FractureNetwork<2>;
  template class FractureNetwork<3>;
} // namespace PolyFrac
