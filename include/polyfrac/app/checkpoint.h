#ifndef polyfrac_app_checkpoint_h
#define polyfrac_app_checkpoint_h

#include <polyfrac/app/parameters.h>

#include <mpi.h>

#include <csignal>
#include <stdexcept>
#include <string>

namespace PolyFrac
{
  /**
   * The checkpoint of a time-dependent run (`Output/Checkpoint interval`,
   * and on SIGINT or SIGTERM after the step in progress), from which
   * `polyfrac FILE.prm --resume` continues.
   *
   * A checkpoint is the file `checkpoint` of the output directory. Rank 0
   * writes it to `checkpoint.tmp` and renames that file, so a run killed
   * while writing leaves the previous checkpoint whole. It holds a text
   * header, which read() checks before anything else: the format, the
   * PolyFrac version and the scene (Parameters::scene_text(): every entry
   * but the Output entries that do not change the results). The state of
   * the run follows as bytes that the driver (Simulator) composes and reads
   * back (boost binary archives).
   *
   * @code
   *   Checkpoint::write(prm, state_bytes);      // rank 0
   *   const std::string state = Checkpoint::read(prm); // --resume
   * @endcode
   */
  class Checkpoint
  {
  public:
    /** The path of the checkpoint of the scene @p prm. */
    static std::string
    file_name(const Parameters &prm);

    /** Writes @p state with the header of @p prm, atomically (write, then
     * rename); throws, naming the file, if a write fails. */
    static void
    write(const Parameters &prm, const std::string &state);

    /**
     * The state of the checkpoint of @p prm. Throws, naming the file and
     * what is wrong, if there is none, if it was written by another
     * PolyFrac version or in another format, or for another scene (the
     * first entry that differs is named).
     */
    static std::string
    read(const Parameters &prm);
  };



  /**
   * Catches SIGINT and SIGTERM while it lives, so that a time-dependent run
   * ends after the step in progress with a checkpoint instead of losing it:
   * the first such signal is recorded (received()); a second one ends the
   * program at once (the default action, restored by the first). The
   * previous actions come back when the object is destroyed.
   */
  class StopSignals
  {
  public:
    /** Installs the handler. */
    StopSignals();

    /** Restores the previous actions. */
    ~StopSignals();

    StopSignals(const StopSignals &) = delete;
    StopSignals &
    operator=(const StopSignals &) = delete;

    /**
     * The signal received on any rank of @p communicator since the
     * construction (the largest number if several), 0 if none: a
     * collective call, so that all ranks stop after the same step.
     */
    static int
    received(const MPI_Comm communicator);

  private:
    struct sigaction previous_interrupt, previous_terminate;
  };



  /**
   * Thrown on every rank when a run stops on a signal after writing its
   * checkpoint; main() prints what() and exits with 128 + the signal's
   * number, the status of a process ended by that signal.
   */
  class StoppedBySignal : public std::runtime_error
  {
  public:
    /** Stopped by @p signal; @p message says where and how to resume. */
    StoppedBySignal(const int signal, const std::string &message)
      : std::runtime_error(message)
      , signal(signal)
    {}

    /** The signal (SIGINT or SIGTERM). */
    const int signal;
  };
} // namespace PolyFrac

#endif
