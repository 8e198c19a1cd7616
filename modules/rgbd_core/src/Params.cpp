#include "rgbd_core/Params.h"

#include <mrpt/system/string_utils.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace hrgbd {
namespace {

std::string number(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

bool unbounded(double v) { return std::abs(v) >= 1e300; }

}  // namespace

std::string Range::why(double v) const {
  const bool below = lo_open ? !(v > lo) : !(v >= lo);
  const bool over = hi_open ? !(v < hi) : !(v <= hi);
  if (!below && !over) return "";
  // (a value beyond an "unbounded" end, 1e300 or more, gets the full range below)
  if (unbounded(hi) && below)
    return std::string("must be ") + (lo_open ? "> " : ">= ") + number(lo);
  if (unbounded(lo) && over) return std::string("must be ") + (hi_open ? "< " : "<= ") + number(hi);
  return "must be in " + std::string(lo_open ? "(" : "[") + number(lo) + ", " + number(hi) +
         (hi_open ? ")" : "]");
}

std::string OneOf::why(const std::string& v) const {
  if (std::find(names.begin(), names.end(), v) != names.end()) return "";
  return "must be " + params_detail::commentOf(*this);
}

std::string OneOf::why(const std::vector<std::string>& v) const {
  for (const auto& w : v)
    if (!why(w).empty()) return "'" + w + "' is not one of " + params_detail::commentOf(*this);
  return "";
}

std::string NonEmpty::why(const std::vector<std::string>& v) const {
  return v.empty() ? "the list is empty" : "";
}

namespace params_detail {
namespace {

[[noreturn]] void failSyntax(const std::string& section, const std::string& key,
                             const std::string& raw, const std::string& why) {
  throw ConfigError("[" + section + "] " + key + " = '" + raw + "': " + why);
}

}  // namespace

std::string rawValue(const mrpt::config::CConfigFileBase& c, const std::string& section,
                     const std::string& key) {
  // MRPT cuts the value at the first "//" that follows a blank, so "key = // text" keeps the
  // comment as its value, and '#' or ';' are comments only at the start of a line.
  const auto v = c.read_string(section, key, "");
  if (v.rfind("//", 0) == 0)
    failSyntax(section, key, v,
               "MRPT reads this comment as the value; leave the value empty without a comment");
  for (std::size_t i = 0; i < v.size(); ++i)
    if ((v[i] == '#' || v[i] == ';') &&
        (i == 0 || std::isspace(static_cast<unsigned char>(v[i - 1]))))
      failSyntax(section, key, v,
                 std::string("'") + v[i] +
                     "' after '=' is not a comment for MRPT, it is read as part of the value; "
                     "use '//' for a comment after a value");
  return v;
}

void parse(const std::string& raw, int& v, const std::string& section, const std::string& key) {
  char* end = nullptr;
  errno = 0;
  const long l = std::strtol(raw.c_str(), &end, 10);
  if (raw.empty() || *end != '\0') failSyntax(section, key, raw, "expects an integer");
  if (errno == ERANGE || l < INT_MIN || l > INT_MAX)
    failSyntax(section, key, raw, "integer out of range");
  v = static_cast<int>(l);
}

void parse(const std::string& raw, double& v, const std::string& section, const std::string& key) {
  char* end = nullptr;
  errno = 0;
  const double d = std::strtod(raw.c_str(), &end);
  if (raw.empty() || *end != '\0') failSyntax(section, key, raw, "expects a number");
  if (!std::isfinite(d) || errno == ERANGE)
    failSyntax(section, key, raw, "expects a finite number in the range of a double");
  v = d;
}

void parse(const std::string& raw, bool& v, const std::string& section, const std::string& key) {
  // The spellings MRPT's read_bool() gives a meaning to; any other is read as false by it.
  const auto l = mrpt::system::lowerCase(raw);
  if (l == "true" || l == "yes" || l == "1")
    v = true;
  else if (l == "false" || l == "no" || l == "0")
    v = false;
  else
    failSyntax(section, key, raw, "expects true or false");
}

void parse(const std::string& raw, std::string& v, const std::string&, const std::string&) {
  v = raw;
}

void parse(const std::string& raw, std::vector<std::string>& v, const std::string&,
           const std::string&) {
  v.clear();
  std::istringstream in(raw);
  for (std::string w; in >> w;) v.push_back(w);
}

void failCheck(const std::string& section, const std::string& key, const std::string& value,
               const std::string& why, const std::string& comment) {
  std::string msg = "[" + section + "] " + key + " = " + value + ": " + why;
  if (!comment.empty()) msg += " (" + comment + ")";
  throw ConfigError(msg);
}

std::string show(double v) { return number(v); }
std::string show(const std::string& v) { return "'" + v + "'"; }
std::string show(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& w : v) s += (s.empty() ? "" : " ") + w;
  return "'" + s + "'";
}

void Lister::add(const std::string& key) {
  if (std::find(keys.begin(), keys.end(), key) != keys.end())
    throw std::logic_error("INI key '" + key + "' declared twice in one section");
  keys.push_back(key);
}

}  // namespace params_detail
}  // namespace hrgbd
