#ifndef polyfrac_base_law_registry_h
#define polyfrac_base_law_registry_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>

#include <polyfrac/base/parameter_extensions.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The fracture faces a law is created for: the centroid of each face
   * (where expressions are evaluated) and the index of its fracture (for
   * data given per fracture), and the number of fractures. Empty when the
   * law is created only to read and check its entries.
   */
  template <int dim>
  struct FaceSites
  {
    /** x̄_σ per fracture face. */
    std::vector<Point<dim>> centroids;
    /** The fracture of each face (an index into the fractures of the
     * scene, in the order of Fractures/Segments, Polygons or Gmsh
     * physical tags). */
    std::vector<unsigned int> fractures;
    /** The number of fractures of the scene (0: not known, the entries
     * are only checked). */
    unsigned int n_fractures = 0;
  };



  /**
   * Where the laws of one kind are chosen: a specialisation for each law
   * interface gives the subsection, the entry that chooses a law, the
   * default law and the first sentence of the entry's documentation (see
   * FrictionLaw and ApertureLaw). A kind whose entry may also list one law
   * per fracture has `per_fracture = true` and a function
   * `combine<dim>(laws, faces)` that makes one law of them, each fracture
   * face following the law of its fracture; otherwise `per_fracture =
   * false`.
   */
  template <template <int> class LawInterface>
  struct LawChoice;



  /**
   * The laws of one kind (friction laws, aperture laws) that registered
   * themselves from their own files, and the entry of the parameter file
   * that chooses one of them (ASPECT's plugin lists, in deal.II idiom). A
   * law is one file: its class, derived from @p LawInterface<dim>, and a
   * Registration object, which gives its name (a value of the choosing
   * entry), a description, the entries of the subsection it reads and how
   * to declare those it owns. The registry adds the choice and the laws'
   * entries to the subsection as a ParameterExtension: the subsection's
   * parameters declare them, check the chosen law's entries by
   * constructing it once, and keep them for create().
   */
  template <template <int> class LawInterface>
  class LawRegistry
  {
  public:
    /**
     * A law's factory: the law for the fracture faces @p faces (none:
     * only read and check the entries), reading its
     * entries from @p prm (the subsection entered, or the snapshot of
     * create()); throws, naming the file of @p context and the entry, on
     * a wrong value.
     */
    template <int dim>
    using Factory = std::function<
      std::unique_ptr<LawInterface<dim>>(ParameterHandler       &prm,
                                         const ParameterContext &context,
                                         const FaceSites<dim>   &faces)>;

    /** What a law registers (see Registration). */
    struct Law
    {
      /** Its value of the choosing entry. */
      std::string name;
      /** One sentence for the entry's documentation. */
      std::string description;
      /** The entries of the subsection it reads. */
      std::vector<std::string> entries;
      /** Declares the entries it owns (an entry is owned by one law; others
       * may read it). */
      std::function<void(ParameterHandler &)> declare;
      /** The factory in 2D. */
      Factory<2> create_2d;
      /** The factory in 3D. */
      Factory<3> create_3d;
    };

    /**
     * Registers the law `LawClass<dim>`, constructed as `LawClass<dim>(prm,
     * context, faces)` (see Factory): a static object of this type in
     * the law's file is its registration line.
     */
    template <template <int> class LawClass>
    struct Registration
    {
      /** Registers LawClass under @p name (see Law for the arguments). */
      Registration(const std::string                             &name,
                   const std::string                             &description,
                   const std::vector<std::string>                &entries,
                   const std::function<void(ParameterHandler &)> &declare)
      {
        register_law(
          {name,
           description,
           entries,
           declare,
           [](ParameterHandler       &prm,
              const ParameterContext &context,
              const FaceSites<2>     &faces) {
             return std::make_unique<LawClass<2>>(prm, context, faces);
           },
           [](ParameterHandler       &prm,
              const ParameterContext &context,
              const FaceSites<3>     &faces) {
             return std::make_unique<LawClass<3>>(prm, context, faces);
           }});
      }
    };

    /** Adds @p law to the laws of the choosing entry (and, with the first
     * law, the extension to its subsection). */
    static void
    register_law(const Law &law)
    {
      if (laws().empty())
        add_parameter_extension(LawChoice<LawInterface>::subsection,
                                extension());
      auto &all = laws();
      all.insert(std::find_if(all.begin(),
                              all.end(),
                              [&](const Law &l) { return law.name < l.name; }),
                 law);
    }

    /** The law that @p snapshot chooses (the extension's entries at the
     * top level, as the subsection's parameters keep them), for the
     * fracture faces @p faces. */
    template <int dim>
    static std::unique_ptr<LawInterface<dim>>
    create(ParameterHandler       &snapshot,
           const ParameterContext &context,
           const FaceSites<dim>   &faces)
    {
      const std::vector<const Law *> laws = chosen(snapshot);
      if (laws.size() == 1)
        return factory<dim>(*laws[0])(snapshot, context, faces);
      using Choice = LawChoice<LawInterface>;
      AssertThrow(faces.n_fractures == 0 || laws.size() == faces.n_fractures,
                  ExcMessage(
                    context.where(Choice::subsection) + ": <" + Choice::entry +
                    "> = " + snapshot.get(Choice::entry) + " lists " +
                    std::to_string(laws.size()) + " laws, but the scene has " +
                    std::to_string(faces.n_fractures) +
                    " fractures: give one law for every fracture, "
                    "or one per fracture in the order of "
                    "Fractures/Segments, Polygons or Gmsh physical "
                    "tags."));
      std::vector<std::unique_ptr<LawInterface<dim>>> per_fracture;
      for (const Law *law : laws)
        per_fracture.push_back(factory<dim>(*law)(snapshot, context, faces));
      return Choice::template combine<dim>(std::move(per_fracture), faces);
    }

  private:
    /** The laws in the order of their names (the order in which the files
     * register them is not defined). A function's static, so that it
     * exists before the registration objects use it. */
    static std::vector<Law> &
    laws()
    {
      static std::vector<Law> all;
      return all;
    }

    /** The laws chosen in @p prm: one, or one per fracture (the entry's
     * pattern admits no other names). */
    static std::vector<const Law *>
    chosen(ParameterHandler &prm)
    {
      std::vector<const Law *> result;
      const auto              &all = laws();
      for (const std::string &name : Utilities::split_string_list(
             prm.get(LawChoice<LawInterface>::entry)))
        {
          const auto law =
            std::find_if(all.begin(), all.end(), [&](const Law &l) {
              return l.name == name;
            });
          Assert(law != all.end(), ExcInternalError());
          result.push_back(&*law);
        }
      return result;
    }

    /** The factory of @p law in dimension dim. */
    template <int dim>
    static const Factory<dim> &
    factory(const Law &law)
    {
      if constexpr (dim == 2)
        return law.create_2d;
      else
        return law.create_3d;
    }

    /** The choosing entry, the laws' own entries, their checks and the
     * entries the chosen law leaves unused. */
    static ParameterExtension
    extension()
    {
      using Choice = LawChoice<LawInterface>;
      ParameterExtension extension;
      extension.entries = []() {
        std::vector<std::string> entries = {Choice::entry};
        for (const Law &law : laws())
          for (const std::string &entry : law.entries)
            if (std::find(entries.begin(), entries.end(), entry) ==
                entries.end())
              entries.push_back(entry);
        return entries;
      };
      extension.declare = [](ParameterHandler &prm) {
        std::string names, documentation = Choice::documentation;
        for (const Law &law : laws())
          {
            names += (names.empty() ? "" : "|") + law.name;
            documentation += " " + law.name + ": " + law.description;
          }
        if (Choice::per_fracture)
          prm.declare_entry(Choice::entry,
                            Choice::default_law,
                            Patterns::List(Patterns::Selection(names), 1),
                            documentation +
                              " One law for every fracture, or one per "
                              "fracture (in the order of Fractures/Segments, "
                              "Polygons or Gmsh physical tags).");
        else
          prm.declare_entry(Choice::entry,
                            Choice::default_law,
                            Patterns::Selection(names),
                            documentation);
        for (const Law &law : laws())
          law.declare(prm);
      };
      extension.check = [](ParameterHandler       &prm,
                           const ParameterContext &context) {
        for (const Law *law : chosen(prm))
          if (context.dim == 2)
            factory<2> (*law)(prm, context, {});
          else
            factory<3> (*law)(prm, context, {});
      };
      extension.unused_entries = [](ParameterHandler &prm) {
        const std::vector<const Law *> used = chosen(prm);
        const auto                     read = [&](const std::string &entry) {
          return std::any_of(used.begin(), used.end(), [&](const Law *law) {
            return std::find(law->entries.begin(), law->entries.end(), entry) !=
                   law->entries.end();
          });
        };
        std::vector<std::pair<std::string, std::string>> unused;
        for (const Law &other : laws())
          for (const std::string &entry : other.entries)
            if (!read(entry) &&
                std::find_if(unused.begin(), unused.end(), [&](const auto &e) {
                  return e.first == entry;
                }) == unused.end())
              unused.emplace_back(entry,
                                  std::string(Choice::subsection) + "/" +
                                    Choice::entry + " = " +
                                    prm.get(Choice::entry));
        return unused;
      };
      return extension;
    }
  };
} // namespace PolyFrac

#endif
