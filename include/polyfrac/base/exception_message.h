#ifndef polyfrac_base_exception_message_h
#define polyfrac_base_exception_message_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <exception>
#include <sstream>
#include <string>

namespace PolyFrac
{
  /**
   * What @p e says to a user: for a deal.II exception (AssertThrow with
   * ExcMessage) its additional information only, without the file, line,
   * condition and stack trace of what(), which belong to a bug report and
   * not to a message about the input; what() for any other exception.
   */
  inline std::string
  exception_message(const std::exception &e)
  {
    if (const auto *exception = dynamic_cast<const dealii::ExceptionBase *>(&e))
      {
        std::ostringstream info;
        exception->print_info(info);
        return dealii::Utilities::trim(info.str());
      }
    return e.what();
  }
} // namespace PolyFrac

#endif
