#include <deal.II/base/mpi.h>

#include <polyfrac/base/progress_line.h>

#include <unistd.h>

#include <iomanip>
#include <iostream>
#include <sstream>

namespace PolyFrac
{
  ProgressLine::ProgressLine()
    : stream(std::cerr,
             isatty(STDERR_FILENO) != 0 &&
               Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
  {}



  void
  ProgressLine::set_run_state(const std::string &state)
  {
    run_state = state;
  }



  void
  ProgressLine::show(const std::string &status)
  {
    // Back to the start of the line, the text, and the rest of the old
    // line erased (ANSI "erase to end of line").
    stream << '\r' << run_state << (run_state.empty() ? "" : ": ") << status
           << "\033[K" << std::flush;
    shown = true;
  }



  void
  ProgressLine::clear()
  {
    if (!shown)
      return;
    stream << "\r\033[K" << std::flush;
    shown = false;
  }



  ProgressLine &
  progress_line()
  {
    static ProgressLine line;
    return line;
  }



  StepProgress::~StepProgress()
  {
    progress_line().clear();
  }



  void
  StepProgress::show(const std::string &status)
  {
    if (!progress_line().is_active())
      return;
    std::ostringstream text;
    text << status << ", " << std::fixed << std::setprecision(1)
         << timer.wall_time() << " s in this step";
    progress_line().show(text.str());
  }
} // namespace PolyFrac
