#ifndef polyfrac_mesh_mesh_parameters_h
#define polyfrac_mesh_mesh_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <polyfrac/base/parameter_context.h>
#include <polyfrac/base/selection.h>

#include <array>
#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /** Mesh/Source: where the triangulation comes from. */
  enum class MeshSource
  {
    /** A generated box (Lower left corner, Upper right corner,
     * Subdivisions, Cell type). */
    hyper_rectangle,
    /** A gmsh file (File name). */
    gmsh
  };
  /** Mesh/Cell type of a generated box. */
  enum class CellType
  {
    /** Quadrilaterals or hexahedra. */
    hypercube,
    /** Triangles or tetrahedra. */
    simplex
  };
  /** Mesh/Refinement: how level k > 0 of a convergence study is made. */
  enum class MeshRefinement
  {
    /** Every cell is refined once more. */
    uniform,
    /** The cells of the largest error indicators are refined. */
    adaptive
  };
  /** Mesh/Distortion type. */
  enum class DistortionType
  {
    /** An independent perturbation of each vertex. */
    random,
    /** A sine map that bends the faces (Kershaw-like). */
    smooth
  };

  /** The names of MeshSource. */
  template <>
  struct SelectionNames<MeshSource>
  {
    /** The names, in the order of the values. */
    static constexpr std::array<const char *, 2> names = {
      {"hyper rectangle", "gmsh"}};
  };
  /** The names of CellType. */
  template <>
  struct SelectionNames<CellType>
  {
    /** The names, in the order of the values. */
    static constexpr std::array<const char *, 2> names = {
      {"hypercube", "simplex"}};
  };
  /** The names of MeshRefinement. */
  template <>
  struct SelectionNames<MeshRefinement>
  {
    /** The names, in the order of the values. */
    static constexpr std::array<const char *, 2> names = {
      {"uniform", "adaptive"}};
  };
  /** The names of DistortionType. */
  template <>
  struct SelectionNames<DistortionType>
  {
    /** The names, in the order of the values. */
    static constexpr std::array<const char *, 2> names = {{"random", "smooth"}};
  };

  /** The subsection Mesh: the triangulation of level 0, how the levels
   * are refined, distorted and agglomerated. Points have 3 coordinates;
   * those beyond dim are 0. */
  struct MeshParameters
  {
    /** Declares the subsection Mesh for dimension @p dim. */
    static void
    declare_parameters(ParameterHandler &prm, const unsigned int dim);

    /** Reads and checks the subsection Mesh: a box of positive measure, a
     * Local refinement box of ordered corners, a readable gmsh file
     * (written back to @p prm as an absolute path). */
    void
    parse_parameters(ParameterHandler &prm, const ParameterContext &context);

    /** The entries that the choices of the subsection leave unused (those
     * of the box with Source = gmsh, of the distortion without one, ...),
     * but Lower left and Upper right corner. */
    std::vector<UnusedEntry>
    unused_entries() const;

    /** Source. */
    MeshSource source;
    /** Cell type. */
    CellType cell_type;
    /** Lower left corner of the generated box. */
    Point<3> lower_left;
    /** Upper right corner of the generated box. */
    Point<3> upper_right;
    /** Subdivisions: cells per direction of the generated box. */
    std::vector<unsigned int> subdivisions;
    /** Global refinements of level 0 (level k refines k more times). */
    unsigned int global_refinements;
    /** Refinement (how level k > 0 is made). */
    MeshRefinement refinement;
    /** Refined fraction: the fraction of the cells an adaptive cycle
     * refines. */
    double refined_fraction;
    /** Lower corner of the Local refinement box. */
    Point<3> box_lower;
    /** Upper corner of the Local refinement box. */
    Point<3> box_upper;
    /** Local refinements: how often the cells in the box are refined. */
    unsigned int local_refinements;
    /** Fracture refinements: how often the cells touching a fracture are
     * refined (a mesh graded towards the fractures). */
    unsigned int fracture_refinements;
    /** Distortion: vertex displacement relative to the local mesh size. */
    double distortion;
    /** Distortion type. */
    DistortionType distortion_type;
    /** Random seed of the random distortion. */
    unsigned int random_seed;
    /** Cells per polytope of the METIS agglomeration (1: none). */
    unsigned int cells_per_polytope;
    /** A Mesh/Region boxes or Mesh/Boundary boxes item: the cells (the
     * boundary faces) whose centre lies in the closed box from lower to
     * upper get id. */
    struct IdBox
    {
      /** The lower corner. */
      Point<3> lower;
      /** The upper corner. */
      Point<3> upper;
      /** The region (material id) of the cells inside, or the boundary id
       * of the boundary faces inside. */
      unsigned int id;

      /** Whether @p x lies in the closed box (its first dim coordinates). */
      template <int dim>
      bool
      contains(const Point<dim> &x) const
      {
        for (unsigned int d = 0; d < dim; ++d)
          if (x[d] < lower[d] || x[d] > upper[d])
            return false;
        return true;
      }
    };
    /** Region boxes with their Region box ids, in the order given. */
    std::vector<IdBox> region_boxes;
    /** Boundary boxes with their Boundary box ids, in the order given. */
    std::vector<IdBox> boundary_boxes;
    /** File name of the gmsh mesh; a relative name is resolved against
     * the directory of the parameter file when parsed. */
    std::string file_name;

  private:
    /** Reads the boxes of the entry @p boxes_entry and their ids from
     * @p ids_entry (Region boxes or Boundary boxes); throws naming the
     * entries on a malformed box or lists of different lengths. */
    static std::vector<IdBox>
    read_id_boxes(ParameterHandler  &prm,
                  const std::string &boxes_entry,
                  const std::string &ids_entry,
                  const std::string &where,
                  const unsigned int dim);
  };
} // namespace PolyFrac

#endif
