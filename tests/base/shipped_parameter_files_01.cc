// Every parameter file shipped in prm/ parses, and without a warning: a
// warning says that an entry is set that the scene's model or solver does
// not use (Parameters::warnings), so a scene that carried one would run
// while ignoring part of what it says. Prints each file's dimension, model,
// solver and mesh; the test fails (exit status) if a file does not parse or
// warns.

#include <polyfrac/app/parameters.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

using namespace PolyFrac;

int
main()
{
  std::vector<std::filesystem::path> files;
  for (const auto &entry :
       std::filesystem::directory_iterator(SOURCE_DIR "/../../prm"))
    if (entry.path().extension() == ".prm")
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  AssertThrow(!files.empty(), ExcMessage("No parameter file in prm/."));

  unsigned int n_warning_files = 0;
  for (const auto &file : files)
    {
      const unsigned int dim = Parameters::read_dimension(file.string());
      Parameters         prm(dim);
      prm.parse(file.string());
      std::cout << file.filename().string() << ": dimension " << dim << ", "
                << prm.model << ", Linear solver/Method = "
                << selection_name(prm.solver.method) << ", "
                << "mesh: " << selection_name(prm.mesh.source) << std::endl;
      for (const std::string &warning : prm.warnings)
        std::cout << "  warning: " << warning << std::endl;
      n_warning_files += !prm.warnings.empty();
    }
  AssertThrow(n_warning_files == 0,
              ExcMessage(std::to_string(n_warning_files) +
                         " shipped parameter files set entries that their "
                         "scene does not use (the warnings above)."));
  std::cout << files.size() << " parameter files, none with a warning"
            << std::endl;
}
