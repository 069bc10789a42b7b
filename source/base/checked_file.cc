#include <deal.II/base/exceptions.h>

#include <polyfrac/base/checked_file.h>

namespace PolyFrac
{
  namespace
  {
    /** Throws naming @p path and @p stage unless @p ok. */
    void
    check_stage(const bool                   ok,
                const std::filesystem::path &path,
                const std::string           &stage)
    {
      AssertThrow(ok,
                  dealii::ExcMessage(
                    "Cannot write <" + path.string() + ">: " + stage +
                    " failed (is the disk full, or the directory "
                    "not writable?). The file is incomplete."));
    }
  } // namespace



  void
  write_checked(const std::filesystem::path               &path,
                const std::function<void(std::ostream &)> &write)
  {
    std::ofstream out(path);
    check_stage(out.is_open(), path, "opening it");
    write(out);
    check_stage(out.good(), path, "writing");
    out.flush();
    check_stage(out.good(), path, "flushing");
    out.close();
    check_stage(!out.fail(), path, "closing");
  }



  void
  check_flushed(std::ofstream &out, const std::filesystem::path &path)
  {
    out.flush();
    check_stage(out.good(), path, "writing a row");
  }
} // namespace PolyFrac
