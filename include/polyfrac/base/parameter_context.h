#ifndef polyfrac_base_parameter_context_h
#define polyfrac_base_parameter_context_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * What a component that parses its own subsection knows of the scene
   * besides its entries: the parameter file (named in every message), the
   * dimension, the constants of the expressions and gravity.
   *
   * Each component's parameters (MeshParameters, FlowParameters, ...)
   * follow one pattern, deal.II's and ASPECT's:
   * @code
   *   static void declare_parameters(ParameterHandler &prm,
   *                                  const unsigned int dim);
   *   void parse_parameters(ParameterHandler &prm,
   *                         const ParameterContext &context);
   * @endcode
   * Both enter and leave the component's subsections themselves; the parse
   * turns every choice into a type (an enum, a number, a checked
   * expression) and throws, naming the file and the entry, on every value
   * it refuses. A component whose entries depend on its own choices lists
   * those the choices leave unused (`unused_entries()`), for the warnings.
   */
  struct ParameterContext
  {
    /** The parameter file, for the messages. */
    std::string file_name;
    /** The space dimension. */
    unsigned int dim;
    /** Expressions/Function constants, as name -> value. */
    std::map<std::string, double> constants;
    /** Gravity/Vector: the acceleration of gravity g in m/s² (components
     * beyond dim are zero); zero (the default) means no gravity. */
    Tensor<1, 3> gravity;

    /** Whether Gravity/Vector is not zero. */
    bool
    has_gravity() const
    {
      return gravity.norm() > 0;
    }

    /** The elevation of @p x: its coordinate along −g/|g| (0 without
     * gravity). */
    template <int dim>
    double
    elevation(const Point<dim> &x) const
    {
      if (!has_gravity())
        return 0;
      double along_g = 0;
      for (unsigned int d = 0; d < dim; ++d)
        along_g += gravity[d] * x[d];
      return -along_g / gravity.norm();
    }

    /** "In <file>, subsection <@p subsection>": how a message starts. */
    std::string
    where(const std::string &subsection) const;

    /** The directory of file_name ("" for the current one): relative paths
     * of the parameter file start there. */
    std::string
    directory() const;

    /**
     * The expression @p expression of entry @p entry ("Flow/Matrix
     * source") with @p n_components components (0: dim; ';' separates
     * them, the single value 0 means zero in every component), parsed
     * with the constants; throws naming the file, the entry and
     * muparser's reason. Returns it trimmed, a 0 written out in every
     * component.
     */
    std::string
    checked_expression(const std::string &entry,
                       const std::string &expression,
                       const unsigned int n_components) const;
  };

  /**
   * An entry that a choice leaves unused ("Mesh/Refined fraction") with the
   * choice ("Mesh/Refinement = uniform"): warned about when it is set.
   */
  using UnusedEntry = std::pair<std::string, std::string>;

  /** Whether the boundary id @p id is among the boundary ids @p ids (an
   * entry such as Flow/Pressure boundary ids). */
  bool
  listed(const std::vector<unsigned int> &ids, const unsigned int id);

  /**
   * The readers that the components' parse_parameters() share: points,
   * lists of ids, bounded numbers, paths.
   */
  namespace ParameterParsing
  {
    /** "0; 0" or "0; 0; 0": the default of a vector expression. */
    std::string
    zero_vector(const unsigned int dim);

    /** @p value repeated @p dim times, comma separated: the default of a
     * point. */
    std::string
    repeated(const std::string &value, const unsigned int dim);

    /** Parses "x, y[, z]" into a Point<3> (unused components zero);
     * throws naming @p where. */
    Point<3>
    parse_point(const std::string &text,
                const unsigned int dim,
                const std::string &where);

    /** Parses "p : p : p ; p : p ..." into lists of points. */
    std::vector<std::vector<Point<3>>>
    parse_point_lists(const std::string &text,
                      const unsigned int dim,
                      const std::string &where);

    /**
     * The integers of the list @p text of entry @p entry (a Patterns::List
     * of integers); throws, naming the entry (@p where: file and
     * subsection), if one is listed twice.
     */
    template <typename Integer>
    std::vector<Integer>
    read_ids(const std::string &text,
             const std::string &entry,
             const std::string &where)
    {
      std::vector<Integer> ids;
      for (const std::string &item : Utilities::split_string_list(text))
        {
          const Integer id = Utilities::string_to_int(item);
          AssertThrow(std::find(ids.begin(), ids.end(), id) == ids.end(),
                      ExcMessage(where + ": <" + entry + "> lists " + item +
                                 " twice; list each once."));
          ids.push_back(id);
        }
      return ids;
    }

    /** Throws, naming both entries, if the lists @p a (of entry
     * @p entry_a) and @p b share an id. */
    template <typename Integer>
    void
    check_disjoint(const std::vector<Integer> &a,
                   const std::string          &entry_a,
                   const std::vector<Integer> &b,
                   const std::string          &entry_b,
                   const std::string          &where)
    {
      for (const Integer id : b)
        AssertThrow(std::find(a.begin(), a.end(), id) == a.end(),
                    ExcMessage(where + ": boundary id " + std::to_string(id) +
                               " is listed in both <" + entry_a + "> and <" +
                               entry_b +
                               ">; give each boundary one kind of data."));
    }

    /** Whether the expression @p text names the time t (as an identifier,
     * not inside another name). */
    bool
    uses_time(const std::string &text);

    /** The number @p text if it is a finite double between @p lower and
     * @p upper (each bound included or not), else nothing: the check the
     * readers of numbers share, each with its own message. */
    std::optional<double>
    checked_number(const std::string &text,
                   const double       lower,
                   const bool         lower_included,
                   const double       upper,
                   const bool         upper_included);

    /**
     * The double @p entry of the current subsection of @p prm; throws,
     * naming @p where ("In <file>, subsection <S>: ") and the entry, unless
     * it lies in @p range ("in (0, 1)", "> 0 (Pa s)"), i.e. between
     * @p lower and @p upper, each bound included or not; @p why is added
     * to the message.
     */
    double
    bounded_double(ParameterHandler  &prm,
                   const std::string &where,
                   const std::string &entry,
                   const double       lower,
                   const bool         lower_included,
                   const double       upper,
                   const bool         upper_included,
                   const std::string &range,
                   const std::string &why = "");

    /**
     * The entry @p entry of the current subsection of @p prm as a list of
     * doubles, one for all fractures or one per fracture, each checked as
     * by bounded_double(); an item that reads @p keyword (if not empty)
     * gives 0. Throws naming @p where and the entry otherwise. The length
     * is checked against the fractures by the caller, who knows them
     * (check_fracture_count()).
     */
    std::vector<double>
    per_fracture_doubles(ParameterHandler  &prm,
                         const std::string &where,
                         const std::string &entry,
                         const double       lower,
                         const bool         lower_included,
                         const std::string &range,
                         const std::string &keyword = "");

    /** Throws, naming @p where (the file and subsection) and @p entry,
     * unless the list @p values that per_fracture_doubles() read has one
     * value or @p n_fractures. */
    void
    check_fracture_count(const std::vector<double> &values,
                         const unsigned int         n_fractures,
                         const std::string         &where,
                         const std::string         &entry);

    /** The value for fracture @p fracture of a list that
     * per_fracture_doubles() read: its one value, or the fracture's. */
    inline double
    per_fracture_value(const std::vector<double> &values,
                       const unsigned int         fracture)
    {
      return values.size() == 1 ? values[0] : values.at(fracture);
    }

    /** The entry @p entry of the current subsection of @p prm that reads
     * `auto` or a positive number: 0 for auto, the number otherwise, and
     * -1 for anything else (a number <= 0 or not a number), which the
     * caller refuses naming its range. */
    double
    auto_or_number(ParameterHandler &prm, const std::string &entry);

    /** The directory of @p file_name ("" for a file in the current one). */
    std::string
    directory_of(const std::string &file_name);

    /** @p path taken from @p directory if it is relative (the rule for
     * every path of a parameter file), then written relative to the
     * current directory, so that printed paths do not depend on where the
     * parameter file lies. */
    std::string
    resolved(const std::string &path, const std::string &directory);

    /** @p path as an absolute path, normalised: the form in which paths
     * are written to used_parameters.prm, so that it runs from anywhere. */
    std::string
    absolute_path(const std::string &path);
  } // namespace ParameterParsing
} // namespace PolyFrac

#endif
