#ifndef polyfrac_app_model_registry_h
#define polyfrac_app_model_registry_h

#include <polyfrac/app/model.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace PolyFrac
{
  class Parameters;
  template <int dim>
  class LevelDiscretization;

  /**
   * The models of Model/Model, each registered from its own file (as the
   * friction laws are): the table that gives the selection string, the
   * factory and the entries each model reads. Parameters builds the entry
   * Model/Model from it and warns about the entries the chosen model does
   * not read; make_model() builds the chosen one. Adding a model is its
   * files and one Registration line; nothing else names it.
   */
  namespace ModelRegistry
  {
    /** A model's factory: the model of the scene @p prm on a level. */
    template <int dim>
    using Factory = std::function<std::unique_ptr<Model<dim>>(
      const Parameters               &prm,
      const LevelDiscretization<dim> &discretization)>;

    /** What a model registers (see Registration). */
    struct Description
    {
      /** Its value of Model/Model. */
      std::string name;
      /** One sentence for the entry's documentation. */
      std::string description;
      /**
       * The entries it reads among those that depend on the model
       * ("Subsection/Entry"): the union of all models' lists is the set of
       * model-dependent entries, and one that the chosen model does not
       * list is warned about when it is set. Called once the file is read
       * (it may list the friction laws' entries, registered by their own
       * files).
       */
      std::function<std::vector<std::string>()> entries;
      /** Whether the model steps in time (Time/...) in the scene @p prm. */
      std::function<bool(const Parameters &prm)> steps_in_time;
      /** Whether it gives error indicators (Mesh/Refinement = adaptive). */
      bool has_error_indicators;
      /** The factory in 2D. */
      Factory<2> create_2d;
      /** The factory in 3D. */
      Factory<3> create_3d;
    };

    /** Adds @p model to the models of Model/Model. */
    void
    register_model(const Description &model);

    /** The registered models, in the order of their names. */
    const std::vector<Description> &
    models();

    /** The model named @p name; throws, listing the models, if there is
     * none. */
    const Description &
    find(const std::string &name);

    /** The model-dependent entries: those some model lists. */
    std::vector<std::string>
    model_dependent_entries();

    /**
     * Registers the model `ModelClass<dim>`, constructed as
     * `ModelClass<dim>(prm, discretization)`: a static object of this type
     * in the model's file is its registration line.
     */
    template <template <int> class ModelClass>
    struct Registration
    {
      /** Registers ModelClass under @p name (see Description for the
       * arguments). */
      Registration(
        const std::string                                &name,
        const std::string                                &description,
        const std::function<std::vector<std::string>()>  &entries,
        const std::function<bool(const Parameters &prm)> &steps_in_time,
        const bool                                        has_error_indicators)
      {
        register_model(
          {name,
           description,
           entries,
           steps_in_time,
           has_error_indicators,
           [](const Parameters &prm, const LevelDiscretization<2> &level) {
             return std::make_unique<ModelClass<2>>(prm, level);
           },
           [](const Parameters &prm, const LevelDiscretization<3> &level) {
             return std::make_unique<ModelClass<3>>(prm, level);
           }});
      }
    };
  } // namespace ModelRegistry
} // namespace PolyFrac

#endif
