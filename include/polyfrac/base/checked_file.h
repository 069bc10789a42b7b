#ifndef polyfrac_base_checked_file_h
#define polyfrac_base_checked_file_h

#include <filesystem>
#include <fstream>
#include <functional>
#include <ostream>
#include <string>

namespace PolyFrac
{
  /**
   * Writes the file @p path through @p write and makes sure that every byte
   * reached it: the stream is checked after opening, after @p write, after
   * the flush and after the close, where a full disk or a quota shows
   * (std::ofstream buffers, so a write that fails often only fails there).
   * Throws an ExcMessage naming the file and the failed stage otherwise, so
   * that a truncated file is never reported as written.
   *
   * @code
   *   write_checked(directory / "convergence.csv",
   *                 [&](std::ostream &out) { out << table; });
   * @endcode
   */
  void
  write_checked(const std::filesystem::path               &path,
                const std::function<void(std::ostream &)> &write);

  /**
   * Throws an ExcMessage naming @p path unless @p out, an open stream that
   * is written row by row (a time series), has flushed all its rows
   * without error.
   */
  void
  check_flushed(std::ofstream &out, const std::filesystem::path &path);
} // namespace PolyFrac

#endif
