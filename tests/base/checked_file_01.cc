// write_checked() and check_flushed(): a write that does not reach the disk
// is an error naming the file, never a file listed as written. /dev/full
// (Linux) fails every write with ENOSPC, as a full disk does; std::ofstream
// buffers, so the failure shows at the flush or the close, which is where
// the checks look. Asserted: a file in a writable directory is written in
// full; /dev/full fails (small and large writes, and a row-by-row stream
// at its flush); a file in a missing directory fails at opening. Each
// failure names the file and the stage.

#include <deal.II/base/exceptions.h>

#include <polyfrac/base/checked_file.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

using namespace PolyFrac;

namespace
{
  /** The message of the exception @p write throws, or "" if none. */
  template <typename Write>
  std::string
  failure_of(const Write &write)
  {
    try
      {
        write();
      }
    catch (const dealii::ExceptionBase &e)
      {
        std::ostringstream what;
        e.print_info(what);
        return what.str();
      }
    return "";
  }

  void
  expect_failure(const std::string &what,
                 const std::string &message,
                 const std::string &part)
  {
    AssertThrow(message.find(part) != std::string::npos,
                dealii::ExcMessage(what + ": expected a message with <" + part +
                                   ">, got <" + message + ">"));
    std::cout << what << ": refused, naming " << part << std::endl;
  }
} // namespace



int
main()
{
  const std::string text(100000, 'x');
  const auto        write_text = [&](std::ostream &out) { out << text; };

  write_checked("checked_file_01.txt", write_text);
  std::ifstream      in("checked_file_01.txt");
  std::ostringstream back;
  back << in.rdbuf();
  AssertThrow(back.str() == text, dealii::ExcInternalError());
  std::cout << "A writable file: written in full (" << back.str().size()
            << " bytes)" << std::endl;

  expect_failure("A small write to a full disk",
                 failure_of([] {
                   write_checked("/dev/full",
                                 [](std::ostream &out) { out << "1,2\n"; });
                 }),
                 "Cannot write </dev/full>");
  expect_failure("A large write to a full disk",
                 failure_of([&] { write_checked("/dev/full", write_text); }),
                 "Cannot write </dev/full>: writing failed");
  expect_failure("A missing directory",
                 failure_of([&] {
                   write_checked("no/such/directory/file.csv", write_text);
                 }),
                 "Cannot write <no/such/directory/file.csv>: opening it");
  std::ofstream rows("/dev/full");
  rows << "step,time\n0,0\n";
  expect_failure("A row of a time series on a full disk",
                 failure_of([&] { check_flushed(rows, "/dev/full"); }),
                 "Cannot write </dev/full>: writing a row failed");
}
