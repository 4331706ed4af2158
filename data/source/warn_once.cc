#include <softchain/data/warn_once.h>

#include <mutex>
#include <set>

namespace softchain::data
{
  bool warn_once(const std::string &message, std::ostream &out)
  {
    static std::mutex            guard;
    static std::set<std::string> printed;
    const std::lock_guard<std::mutex> lock(guard);
    if (!printed.insert(message).second)
      return false;
    out << message << '\n';
    return true;
  }
} // namespace softchain::data
