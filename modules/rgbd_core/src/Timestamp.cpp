#include "rgbd_core/Timestamp.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>

namespace hrgbd {
namespace {

using Duration = mrpt::Clock::duration;
using TimePoint = mrpt::Clock::time_point;

// MRPT's clock counts 100 ns ticks from 1601-01-01; UNIX time 0 is this tick.
constexpr std::int64_t kUnixEpochTicks = 116444736000000000LL;
constexpr std::int64_t kTicksPerSecond = 10000000;
constexpr int kTickDecimals = 7;       // 100 ns
constexpr int kMaxIntegerDigits = 11;  // below 1e11 s
static_assert(kMaxFrameSeconds == 1e11);

/** |ticks since 1970| and whether they lie before it; any int64 count (a corrupt rawlog holds
 * anything) without overflow. */
struct UnixTicks {
  bool before = false;
  std::uint64_t magnitude = 0;
};
UnixTicks unixTicks(TimePoint t) {
  const auto count = static_cast<std::uint64_t>(t.time_since_epoch().count());
  const auto epoch = static_cast<std::uint64_t>(kUnixEpochTicks);
  if (t.time_since_epoch().count() >= kUnixEpochTicks) return {false, count - epoch};
  return {true, epoch - count};  // modulo 2^64: right for negative counts too
}

}  // namespace

// Hand-written: std::from_chars and strtod go through a double, which cannot hold today's UNIX
// times to 100 ns (its step near 1.7e9 s is 238 ns), so a 7-decimal stamp would change.
TimePoint parseFrameTime(const std::string& text) {
  std::size_t i = 0;
  const bool negative = i < text.size() && text[i] == '-';
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  std::string digits;  // the mantissa's digits, without the point
  long point = -1;     // how many of them stand before the point
  for (; i < text.size(); ++i) {
    if (std::isdigit(static_cast<unsigned char>(text[i])))
      digits += text[i];
    else if (text[i] == '.' && point < 0)
      point = static_cast<long>(digits.size());
    else
      break;
  }
  if (point < 0) point = static_cast<long>(digits.size());
  long exponent = 0;
  if (!digits.empty() && i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    const bool minus = i < text.size() && text[i] == '-';
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    const std::size_t start = i;
    for (; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i)
      exponent = std::min(exponent * 10 + (text[i] - '0'), 100000L);
    if (i == start) digits.clear();  // "1e" is not a number
    if (minus) exponent = -exponent;
  }
  if (digits.empty() || i != text.size())
    throw std::invalid_argument("'" + text + "' is not a time stamp in seconds");
  const auto first = digits.find_first_not_of('0');
  if (first == std::string::npos) return TimePoint(Duration(kUnixEpochTicks));  // zero
  // The value is 0.<digits> x 10^integer_digits, digits[0] != '0'.
  digits = digits.substr(first);
  const long integer_digits = point + exponent - static_cast<long>(first);
  if (negative)
    throw std::invalid_argument("time stamp " + text +
                                " is negative: frame times are seconds of UNIX time, from 1970");
  if (integer_digits > kMaxIntegerDigits)
    throw std::invalid_argument("time stamp " + text +
                                " is not below 1e11 s (the year 5138): frame times are seconds, "
                                "not milliseconds, microseconds or nanoseconds");
  const long kept = integer_digits + kTickDecimals;  // digits down to 100 ns
  for (long k = std::max(0L, kept); k < static_cast<long>(digits.size()); ++k)
    if (digits[k] != '0')
      throw std::invalid_argument("time stamp " + text +
                                  " is finer than 100 ns, the resolution of MRPT's clock");
  std::int64_t ticks = 0;  // < 1e18: at most 18 digits
  for (long k = 0; k < kept; ++k)
    ticks = ticks * 10 + (k < static_cast<long>(digits.size()) ? digits[k] - '0' : 0);
  return TimePoint(Duration(kUnixEpochTicks + ticks));
}

void checkFrameTime(TimePoint t) {
  if (t == TimePoint()) throw std::invalid_argument("the frame has no time stamp");
  const auto u = unixTicks(t);
  if (u.before && u.magnitude > 0)
    throw std::invalid_argument("time stamp " + formatFrameTime(t) + " lies before 1970");
  if (u.magnitude >= static_cast<std::uint64_t>(kMaxFrameSeconds) * kTicksPerSecond)
    throw std::invalid_argument("time stamp " + formatFrameTime(t) +
                                " is not below 1e11 s (the year 5138)");
}

TimePoint frameTimeFromSeconds(double seconds) {
  if (!(seconds >= 0 && seconds < kMaxFrameSeconds))
    throw std::invalid_argument("time " + formatSeconds(seconds) +
                                " s is not in [0, 1e11) s of UNIX time");
  return TimePoint(Duration(kUnixEpochTicks + std::llround(seconds * kTicksPerSecond)));
}

double frameSeconds(TimePoint t) {
  const auto u = unixTicks(t);
  const double s = static_cast<double>(u.magnitude) / static_cast<double>(kTicksPerSecond);
  return u.before ? -s : s;
}

std::string formatFrameTime(TimePoint t) {
  const auto u = unixTicks(t);
  char buf[48];
  std::snprintf(buf, sizeof buf, "%s%llu.%07llu00", u.before ? "-" : "",
                static_cast<unsigned long long>(u.magnitude / kTicksPerSecond),
                static_cast<unsigned long long>(u.magnitude % kTicksPerSecond));
  return buf;
}

std::string formatSeconds(double seconds) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, seconds);
  return std::string(buf, r.ptr);
}

}  // namespace hrgbd
