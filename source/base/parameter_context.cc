#include <deal.II/base/exceptions.h>

#include <polyfrac/base/expressions.h>
#include <polyfrac/base/parameter_context.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <regex>
#include <sstream>

namespace PolyFrac
{
  std::string
  ParameterContext::where(const std::string &subsection) const
  {
    return "In <" + file_name + ">, subsection <" + subsection + ">";
  }



  std::string
  ParameterContext::directory() const
  {
    return ParameterParsing::directory_of(file_name);
  }



  std::string
  ParameterContext::checked_expression(const std::string &entry,
                                       const std::string &expression,
                                       const unsigned int n_components) const
  {
    const unsigned int expected = n_components == 0 ? dim : n_components;
    std::string        checked  = Utilities::trim(expression);
    if (checked == "0")
      for (unsigned int i = 1; i < expected; ++i)
        checked += "; 0";
    const unsigned int n = Utilities::split_string_list(checked, ';').size();
    AssertThrow(n == expected,
                ExcMessage("In <" + file_name + ">: entry <" + entry +
                           "> has " + std::to_string(n) +
                           " components, expected " + std::to_string(expected) +
                           " separated by ';' (or the single value 0)."));
    // Parsed here, before any mesh is built, so that a typo stops the run
    // at once.
    try
      {
        if (dim == 2)
          make_expression<2>(entry, checked, expected, constants);
        else
          make_expression<3>(entry, checked, expected, constants);
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        AssertThrow(false,
                    ExcMessage("In <" + file_name +
                               ">: " + Utilities::trim(info.str())));
      }
    return checked;
  }



  bool
  listed(const std::vector<unsigned int> &ids, const unsigned int id)
  {
    return std::find(ids.begin(), ids.end(), id) != ids.end();
  }



  namespace ParameterParsing
  {
    std::string
    zero_vector(const unsigned int dim)
    {
      return dim == 2 ? "0; 0" : "0; 0; 0";
    }



    std::string
    repeated(const std::string &value, const unsigned int dim)
    {
      std::string result = value;
      for (unsigned int d = 1; d < dim; ++d)
        result += ", " + value;
      return result;
    }



    Point<3>
    parse_point(const std::string &text,
                const unsigned int dim,
                const std::string &where)
    {
      const std::vector<std::string> parts =
        Utilities::split_string_list(text, ',');
      AssertThrow(parts.size() == dim,
                  ExcMessage(where + ": the point <" + text + "> has " +
                             std::to_string(parts.size()) +
                             " coordinates, expected " + std::to_string(dim) +
                             " (comma separated)."));
      Point<3> p;
      for (unsigned int d = 0; d < dim; ++d)
        {
          try
            {
              p[d] = Utilities::string_to_double(parts[d]);
            }
          catch (...)
            {
              AssertThrow(false,
                          ExcMessage(where + ": <" + parts[d] +
                                     "> is not a number."));
            }
          AssertThrow(std::isfinite(p[d]),
                      ExcMessage(where + ": <" + parts[d] +
                                 "> is not a finite number."));
        }
      return p;
    }



    std::vector<std::vector<Point<3>>>
    parse_point_lists(const std::string &text,
                      const unsigned int dim,
                      const std::string &where)
    {
      std::vector<std::vector<Point<3>>> result;
      for (const std::string &item : Utilities::split_string_list(text, ';'))
        {
          if (item.empty())
            continue;
          std::vector<Point<3>> points;
          for (const std::string &p : Utilities::split_string_list(item, ':'))
            points.push_back(parse_point(p, dim, where));
          result.push_back(points);
        }
      return result;
    }



    bool
    uses_time(const std::string &text)
    {
      static const std::regex identifier(R"([A-Za-z_][A-Za-z0-9_]*)");
      for (auto word =
             std::sregex_iterator(text.begin(), text.end(), identifier);
           word != std::sregex_iterator();
           ++word)
        if (word->str() == "t")
          return true;
      return false;
    }



    double
    bounded_double(ParameterHandler  &prm,
                   const std::string &where,
                   const std::string &entry,
                   const double       lower,
                   const bool         lower_included,
                   const double       upper,
                   const bool         upper_included,
                   const std::string &range,
                   const std::string &why)
    {
      const double value = prm.get_double(entry);
      AssertThrow((lower_included ? value >= lower : value > lower) &&
                    (upper_included ? value <= upper : value < upper),
                  ExcMessage(where + "<" + entry + "> must be " + range +
                             ", not " + prm.get(entry) + why + "."));
      return value;
    }



    std::optional<double>
    checked_number(const std::string &text,
                   const double       lower,
                   const bool         lower_included,
                   const double       upper,
                   const bool         upper_included)
    {
      double value = std::numeric_limits<double>::quiet_NaN();
      try
        {
          value = Utilities::string_to_double(text);
        }
      catch (...)
        {}
      if (std::isfinite(value) &&
          (lower_included ? value >= lower : value > lower) &&
          (upper_included ? value <= upper : value < upper))
        return value;
      return std::nullopt;
    }



    void
    check_fracture_count(const std::vector<double> &values,
                         const unsigned int         n_fractures,
                         const std::string         &where,
                         const std::string         &entry)
    {
      AssertThrow(values.size() == 1 || values.size() == n_fractures,
                  ExcMessage(where + ": <" + entry + "> lists " +
                             std::to_string(values.size()) +
                             " values, but the scene has " +
                             std::to_string(n_fractures) +
                             " fractures: give one value for every fracture, "
                             "or one per fracture (in the order of "
                             "Fractures/Segments, Polygons or Gmsh physical "
                             "tags)."));
    }



    std::vector<double>
    per_fracture_doubles(ParameterHandler  &prm,
                         const std::string &where,
                         const std::string &entry,
                         const double       lower,
                         const bool         lower_included,
                         const std::string &range,
                         const std::string &keyword)
    {
      const std::vector<std::string> items =
        Utilities::split_string_list(prm.get(entry));
      std::vector<double> values;
      for (const std::string &item : items)
        {
          if (!keyword.empty() && item == keyword)
            {
              values.push_back(0);
              continue;
            }
          const std::optional<double> value =
            checked_number(item,
                           lower,
                           lower_included,
                           std::numeric_limits<double>::infinity(),
                           false);
          AssertThrow(value.has_value(),
                      ExcMessage(where + "<" + entry + "> = " + prm.get(entry) +
                                 ": each value must be " + range +
                                 (keyword.empty() ? "" : " or " + keyword) +
                                 ", not <" + item +
                                 "> (one value for every fracture, or one "
                                 "per fracture in the order of Fractures/"
                                 "Segments, Polygons or Gmsh physical tags)."));
          values.push_back(*value);
        }
      AssertThrow(!values.empty(),
                  ExcMessage(where + "<" + entry +
                             "> is empty: give one value for every fracture, "
                             "or one per fracture."));
      return values;
    }



    double
    auto_or_number(ParameterHandler &prm, const std::string &entry)
    {
      const std::string text = Utilities::trim(prm.get(entry));
      if (text == "auto")
        return 0;
      try
        {
          const double value = Utilities::string_to_double(text);
          return value > 0 ? value : -1;
        }
      catch (...)
        {
          return -1;
        }
    }



    std::string
    directory_of(const std::string &file_name)
    {
      return std::filesystem::path(file_name).parent_path().string();
    }



    std::string
    resolved(const std::string &path, const std::string &directory)
    {
      if (path.empty() || directory.empty() || path[0] == '/')
        return path;
      return std::filesystem::proximate(std::filesystem::path(directory) / path)
        .string();
    }



    std::string
    absolute_path(const std::string &path)
    {
      return std::filesystem::absolute(path).lexically_normal().string();
    }
  } // namespace ParameterParsing
} // namespace PolyFrac
