#ifndef polyfrac_base_region_values_h
#define polyfrac_base_region_values_h

#include <deal.II/base/types.h>

#include <map>
#include <set>
#include <string>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * A material property given once for the whole domain ("3e9") or per
   * region ("0: 3e9, 1: 6e9"). A region is the material id of the cells:
   * a gmsh physical volume (a physical surface in 2D) or a Mesh/Region box;
   * a polytope has the region of its cells (PolytopalMesh::Cell::region).
   *
   * Given per region, the property must name every region of the mesh and
   * no other (check_regions(), once the mesh is built): a region left out
   * or misspelt is refused, never given a default.
   */
  class RegionValues
  {
  public:
    /** The value @p value in every region. */
    RegionValues(const double value = 0);

    /**
     * Reads @p text, the entry @p entry (named with @p where, "In <file>,
     * subsection <S>: ") as one value or a list of `region: value`; throws
     * naming the entry unless every value lies in @p range, between
     * @p lower and @p upper, each bound included or not.
     */
    static RegionValues
    parse(const std::string &text,
          const std::string &where,
          const std::string &entry,
          const double       lower,
          const bool         lower_included,
          const double       upper,
          const bool         upper_included,
          const std::string &range);

    /** Whether @p text is a list of `region: value` items (a region id,
     * that is a non-negative integer, before each colon). */
    static bool
    is_region_list(const std::string &text);

    /** The value in region @p region. */
    double
    operator()(const types::material_id region) const;

    /** Whether region @p region has a value (every region has one if
     * the property is uniform). */
    bool
    has(const types::material_id region) const;

    /** Whether one value holds everywhere. */
    bool
    is_uniform() const;

    /** The one value; throws naming @p where, @p entry and @p user (what
     * needs a single value, e.g. an analytic solution) if given per
     * region. */
    double
    uniform_value(const std::string &where,
                  const std::string &entry,
                  const std::string &user) const;

    /** The regions and their values (empty if uniform). */
    const std::map<types::material_id, double> &
    per_region() const;

    /**
     * Throws, naming @p where and @p entry, unless a property given per
     * region lists exactly the regions @p mesh_regions of the mesh.
     */
    void
    check_regions(const std::set<types::material_id> &mesh_regions,
                  const std::string                  &where,
                  const std::string                  &entry) const;

  private:
    /** The value everywhere, if no region is listed. */
    double uniform;
    /** The value per region. */
    std::map<types::material_id, double> by_region;
  };
} // namespace PolyFrac

#endif
