#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <polyfrac/app/checkpoint.h>
#include <polyfrac/base/checked_file.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

namespace PolyFrac
{
  namespace
  {
    /** The format of the checkpoint files; raised when their content
     * changes (2: the time series they carry has the column
     * injection_pressure). */
    constexpr unsigned int checkpoint_format = 2;

    /** The signal recorded by the handler of StopSignals. */
    volatile std::sig_atomic_t received_signal = 0;

    extern "C" void
    record_signal(const int signal)
    {
      received_signal = signal;
    }

    /** The entries of a parameter text (ParameterHandler::ShortPRM), by
     * their path Subsection/Entry. */
    std::map<std::string, std::string>
    entries(const std::string &text)
    {
      std::map<std::string, std::string> values;
      std::vector<std::string>           subsections;
      std::istringstream                 in(text);
      for (std::string line; std::getline(in, line);)
        {
          line = Utilities::trim(line);
          if (line.rfind("subsection ", 0) == 0)
            subsections.push_back(Utilities::trim(line.substr(11)));
          else if (line == "end" && !subsections.empty())
            subsections.pop_back();
          else if (line.rfind("set ", 0) == 0 && line.find('=') != line.npos)
            {
              std::string path;
              for (const std::string &subsection : subsections)
                path += subsection + '/';
              const auto equal = line.find('=');
              path += Utilities::trim(line.substr(4, equal - 4));
              values[path] = Utilities::trim(line.substr(equal + 1));
            }
        }
      return values;
    }

    /** The first entry whose value differs between the scene texts
     * @p written (the checkpoint's) and @p current, as a sentence. */
    std::string
    first_difference(const std::string &written, const std::string &current)
    {
      const auto old_values = entries(written), new_values = entries(current);
      const auto value = [](const std::map<std::string, std::string> &m,
                            const std::string                        &path) {
        const auto entry = m.find(path);
        return entry == m.end() ? std::string("(no such entry)") :
                                  "<" + entry->second + ">";
      };
      for (const auto *values : {&old_values, &new_values})
        for (const auto &[path, unused] : *values)
          if (value(old_values, path) != value(new_values, path))
            return path + " is " + value(old_values, path) +
                   " in the checkpoint and " + value(new_values, path) +
                   " in this run";
      return "their parameters differ";
    }

    /** Reads the line "@p key VALUE" of @p in and returns VALUE (empty if
     * the line is not there). */
    std::string
    header_value(std::istream &in, const std::string &key)
    {
      std::string line;
      std::getline(in, line);
      return line.rfind(key + ' ', 0) == 0 ? line.substr(key.size() + 1) : "";
    }

    /** Reads a block "@p key N\n" followed by N bytes; false if it is not
     * there whole. */
    bool
    read_block(std::istream &in, const std::string &key, std::string &block)
    {
      const std::string size = header_value(in, key);
      if (size.empty() || size.find_first_not_of("0123456789") != size.npos)
        return false;
      block.resize(std::stoull(size));
      in.read(block.data(), block.size());
      return static_cast<std::size_t>(in.gcount()) == block.size();
    }
  } // namespace



  std::string
  Checkpoint::file_name(const Parameters &prm)
  {
    return prm.output.directory + "/checkpoint";
  }



  void
  Checkpoint::write(const Parameters &prm, const std::string &state)
  {
    const std::string name = file_name(prm), temporary = name + ".tmp";
    const std::string scene = prm.scene_text();
    write_checked(temporary, [&](std::ostream &out) {
      out << "PolyFrac checkpoint " << checkpoint_format << '\n'
          << "version " << POLYFRAC_VERSION << '\n'
          << "scene " << scene.size() << '\n'
          << scene << "state " << state.size() << '\n'
          << state;
    });
    std::error_code error;
    std::filesystem::rename(temporary, name, error);
    AssertThrow(!error,
                ExcMessage("Cannot rename <" + temporary + "> to <" + name +
                           ">: " + error.message() + "."));
  }



  std::string
  Checkpoint::read(const Parameters &prm)
  {
    const std::string name = file_name(prm);
    std::ifstream     in(name, std::ios::binary);
    AssertThrow(in,
                ExcMessage("--resume: there is no checkpoint <" + name +
                           "> (a time-dependent run writes one every Output/"
                           "Checkpoint interval steps and when stopped by "
                           "SIGINT or SIGTERM). Run without --resume to "
                           "start from t = 0."));
    const std::string where = "--resume: the checkpoint <" + name + "> ";
    std::string       line;
    std::getline(in, line);
    AssertThrow(line ==
                  "PolyFrac checkpoint " + std::to_string(checkpoint_format),
                ExcMessage(where + "is not a PolyFrac checkpoint of format " +
                           std::to_string(checkpoint_format) +
                           " (its first line is <" + line.substr(0, 40) +
                           ">). Run without --resume to start from t = 0."));
    const std::string version = header_value(in, "version");
    AssertThrow(version == POLYFRAC_VERSION,
                ExcMessage(where + "was written by PolyFrac " + version +
                           ", this is PolyFrac " + POLYFRAC_VERSION +
                           ": its state may not mean the same. Run without "
                           "--resume to start from t = 0."));
    std::string scene, state;
    AssertThrow(read_block(in, "scene", scene) &&
                  read_block(in, "state", state),
                ExcMessage(where + "is cut short (the disk was full, or "
                                   "another program wrote it). Run without "
                                   "--resume to start from t = 0."));
    const std::string current = prm.scene_text();
    AssertThrow(scene == current,
                ExcMessage(where + "is of another scene: " +
                           first_difference(scene, current) +
                           ". Resume with the parameters of the run that "
                           "wrote it, or run without --resume."));
    return state;
  }



  StopSignals::StopSignals()
  {
    received_signal         = 0;
    struct sigaction action = {};
    action.sa_handler       = record_signal;
    sigemptyset(&action.sa_mask);
    // The first signal restores the default action: a second one ends the
    // program at once.
    action.sa_flags = SA_RESETHAND;
    sigaction(SIGINT, &action, &previous_interrupt);
    sigaction(SIGTERM, &action, &previous_terminate);
  }



  StopSignals::~StopSignals()
  {
    sigaction(SIGINT, &previous_interrupt, nullptr);
    sigaction(SIGTERM, &previous_terminate, nullptr);
  }



  int
  StopSignals::received(const MPI_Comm communicator)
  {
    return Utilities::MPI::max(static_cast<int>(received_signal), communicator);
  }
} // namespace PolyFrac
