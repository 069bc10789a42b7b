#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <polyfrac/base/parameter_context.h>
#include <polyfrac/base/region_values.h>

#include <cmath>
#include <regex>

namespace PolyFrac
{
  namespace
  {
    /** "0, 3, 7": the regions of @p regions, for the messages. */
    std::string
    joined(const std::set<types::material_id> &regions)
    {
      std::string text;
      for (const types::material_id region : regions)
        text += (text.empty() ? "" : ", ") + std::to_string(region);
      return text;
    }

    /** What a per-region list reads like, for the messages. */
    const std::string form =
      " (one value for every region, or <region: value, ...> with the "
      "regions' material ids: gmsh physical volumes, physical surfaces in "
      "2D, or Mesh/Region box ids)";
  } // namespace



  RegionValues::RegionValues(const double value)
    : uniform(value)
  {}



  bool
  RegionValues::is_region_list(const std::string &text)
  {
    static const std::regex item(R"(\s*[0-9]+\s*:.*)");
    if (text.find(':') == std::string::npos)
      return false;
    for (const std::string &part : Utilities::split_string_list(text, ','))
      if (!std::regex_match(part, item))
        return false;
    return true;
  }



  RegionValues
  RegionValues::parse(const std::string &text,
                      const std::string &where,
                      const std::string &entry,
                      const double       lower,
                      const bool         lower_included,
                      const double       upper,
                      const bool         upper_included,
                      const std::string &range)
  {
    const auto number = [&](const std::string &item) {
      const std::optional<double> value = ParameterParsing::checked_number(
        item, lower, lower_included, upper, upper_included);
      AssertThrow(value.has_value(),
                  ExcMessage(where + "<" + entry + "> = " + text +
                             ": each value must be " + range + ", not <" +
                             item + ">" + form + "."));
      return *value;
    };
    if (!is_region_list(text))
      return RegionValues(number(Utilities::trim(text)));

    RegionValues values;
    for (const std::string &item : Utilities::split_string_list(text, ','))
      {
        const std::vector<std::string> pair =
          Utilities::split_string_list(item, ':');
        AssertThrow(pair.size() == 2,
                    ExcMessage(where + "<" + entry + "> = " + text +
                               ": the item <" + item +
                               "> is not <region: value>" + form + "."));
        const types::material_id region = Utilities::string_to_int(pair[0]);
        AssertThrow(values.by_region.emplace(region, number(pair[1])).second,
                    ExcMessage(where + "<" + entry + "> = " + text +
                               " gives region " + pair[0] + " twice."));
      }
    return values;
  }



  double
  RegionValues::operator()(const types::material_id region) const
  {
    if (by_region.empty())
      return uniform;
    const auto value = by_region.find(region);
    AssertThrow(value != by_region.end(),
                ExcMessage("No value for region " + std::to_string(region) +
                           ": RegionValues::check_regions() was not called "
                           "on this mesh."));
    return value->second;
  }



  bool
  RegionValues::has(const types::material_id region) const
  {
    return is_uniform() || by_region.count(region) == 1;
  }



  bool
  RegionValues::is_uniform() const
  {
    return by_region.empty();
  }



  double
  RegionValues::uniform_value(const std::string &where,
                              const std::string &entry,
                              const std::string &user) const
  {
    AssertThrow(is_uniform(),
                ExcMessage(where + "<" + entry + "> is given per region, but " +
                           user + " needs one value everywhere."));
    return uniform;
  }



  const std::map<types::material_id, double> &
  RegionValues::per_region() const
  {
    return by_region;
  }



  void
  RegionValues::check_regions(const std::set<types::material_id> &mesh_regions,
                              const std::string                  &where,
                              const std::string                  &entry) const
  {
    if (is_uniform())
      return;
    std::set<types::material_id> listed;
    for (const auto &[region, value] : by_region)
      listed.insert(region);
    for (const types::material_id region : mesh_regions)
      AssertThrow(listed.count(region) == 1,
                  ExcMessage(where + "<" + entry + "> gives regions " +
                             joined(listed) + ", but cells of region " +
                             std::to_string(region) +
                             " have no value; the mesh has the regions " +
                             joined(mesh_regions) + "."));
    for (const types::material_id region : listed)
      AssertThrow(mesh_regions.count(region) == 1,
                  ExcMessage(where + "<" + entry + "> gives region " +
                             std::to_string(region) +
                             ", which no cell of the mesh has; the mesh has "
                             "the regions " +
                             joined(mesh_regions) +
                             " (a Mesh/Region box that holds no cell "
                             "centre, or a misspelt id?)."));
  }
} // namespace PolyFrac
