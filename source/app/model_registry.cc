#include <deal.II/base/exceptions.h>

#include <polyfrac/app/model_registry.h>

#include <algorithm>

namespace PolyFrac
{
  namespace ModelRegistry
  {
    namespace
    {
      /** The models; a function's static, so that it exists before the
       * registration objects of other files use it. */
      std::vector<Description> &
      all()
      {
        static std::vector<Description> models;
        return models;
      }
    } // namespace



    void
    register_model(const Description &model)
    {
      auto &models = all();
      models.insert(std::find_if(models.begin(),
                                 models.end(),
                                 [&](const Description &other) {
                                   return model.name < other.name;
                                 }),
                    model);
    }



    const std::vector<Description> &
    models()
    {
      return all();
    }



    const Description &
    find(const std::string &name)
    {
      std::string names;
      for (const Description &model : all())
        {
          if (model.name == name)
            return model;
          names += (names.empty() ? "" : ", ") + model.name;
        }
      AssertThrow(false,
                  dealii::ExcMessage("Model = " + name +
                                     " is none of the models of this build (" +
                                     names + ")."));
      return all().front();
    }



    std::vector<std::string>
    model_dependent_entries()
    {
      std::vector<std::string> entries;
      for (const Description &model : all())
        for (const std::string &entry : model.entries())
          if (std::find(entries.begin(), entries.end(), entry) == entries.end())
            entries.push_back(entry);
      return entries;
    }
  } // namespace ModelRegistry
} // namespace PolyFrac
