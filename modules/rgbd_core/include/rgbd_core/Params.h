#pragma once
/** \file Params.h
 * INI parameters declared once. A params struct derives from Params<Self> and lists each key in
 * one static template, declare(); loading, saving, the unknown-key check, the typed syntax check
 * and the range checks are all derived from that list:
 *
 * \code
 * struct OrbParams : public Params<OrbParams> {
 *   int n_features = 1000;  //!< [count] most keypoints kept
 *   template <class P, class V>
 *   static void declare(P& p, V& v) {
 *     HRGBD_PARAM(n_features, "[count] most ORB keypoints per frame", Range::atLeast(10));
 *   }
 * };
 * \endcode
 *
 * The key is the field name (HRGBD_PARAM stringifies it). Field types: int, double, bool,
 * std::string, an enum declared with MRPT_ENUM_TYPE_BEGIN / MRPT_FILL_ENUM_CUSTOM_NAME (its names
 * are the INI values, as MRPT's read_enum), and std::vector<std::string> (a space-separated
 * list). Optional checks after the comment: Range (numbers), OneOf (text and lists), NonEmpty
 * (lists). `v.section(p.orb, "ORB")` declares a params struct kept in a section of its own;
 * `v.merge(p.sensor)` one whose keys live in the same section. Rules between several fields go in
 * a `void checkTogether(const std::string& section) const` that hides the base's.
 *
 * Every value is read as MRPT's CConfigFileBase::read_string() returns it (trimmed; a "//" after
 * a blank and what follows dropped) and must then be wholly of the declared type, where MRPT's
 * read_int/read_double/read_bool take "1,5" as 1, "2.7" as 2, "abc" or "" as 0, "maybe" as false
 * and "inf" as a number. A ConfigError names the section and key. */
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/config/CLoadableOptions.h>

#include <string>
#include <type_traits>
#include <vector>

#include "rgbd_core/Config.h"

/** Declares field `name` of `p` to visitor `v`: `HRGBD_PARAM(name, "comment", checks...)`. */
#define HRGBD_PARAM(name, ...) v(p.name, #name, __VA_ARGS__)

namespace hrgbd {

/** Check of a number: inside [lo, hi], each end open or closed, either end unbounded. */
struct Range {
  double lo = -1e300, hi = 1e300;
  bool lo_open = false, hi_open = false;
  static Range atLeast(double lo) { return {lo, 1e300, false, false}; }            //!< [lo, inf)
  static Range above(double lo) { return {lo, 1e300, true, false}; }               //!< (lo, inf)
  static Range closed(double lo, double hi) { return {lo, hi, false, false}; }     //!< [lo, hi]
  static Range open(double lo, double hi) { return {lo, hi, true, true}; }         //!< (lo, hi)
  static Range openClosed(double lo, double hi) { return {lo, hi, true, false}; }  //!< (lo, hi]
  static Range closedOpen(double lo, double hi) { return {lo, hi, false, true}; }  //!< [lo, hi)
  /** "" when `v` is inside, else why not ("must be in (0, 1]"). */
  std::string why(double v) const;
};

/** Check of a text value or of each word of a list: one of `names`. */
struct OneOf {
  std::vector<std::string> names;
  std::string why(const std::string& v) const;
  std::string why(const std::vector<std::string>& v) const;
};

/** Check of a list: at least one word. */
struct NonEmpty {
  std::string why(const std::vector<std::string>& v) const;
};

namespace params_detail {

/** The value of `key` as MRPT reads it; ConfigError for the spellings MRPT misreads as a comment
 * ("key = // text" is read as "// text"; "# text" after a value is part of the value). */
std::string rawValue(const mrpt::config::CConfigFileBase& c, const std::string& section,
                     const std::string& key);

/** Strict parsers: the whole of `raw` must be of the type; ConfigError "[section] key = 'raw':
 * expects ..." otherwise. */
void parse(const std::string& raw, int& v, const std::string& section, const std::string& key);
void parse(const std::string& raw, double& v, const std::string& section, const std::string& key);
void parse(const std::string& raw, bool& v, const std::string& section, const std::string& key);
void parse(const std::string& raw, std::string& v, const std::string& section,
           const std::string& key);
void parse(const std::string& raw, std::vector<std::string>& v, const std::string& section,
           const std::string& key);
template <class E, class = std::enable_if_t<std::is_enum_v<E>>>
void parse(const std::string& raw, E& v, const std::string& section, const std::string& key) {
  v = parseEnum<E>(raw, section, key);
}

/** The value as saved: MRPT's own formatting for numbers and bools, names for enums, words joined
 * by a space for lists. */
template <class T>
void write(mrpt::config::CConfigFileBase& c, const std::string& s, const std::string& key,
           const T& v, const std::string& comment) {
  using mrpt::config::MRPT_SAVE_NAME_PADDING, mrpt::config::MRPT_SAVE_VALUE_PADDING;
  if constexpr (std::is_enum_v<T>) {
    const auto names = enumNames<T>();
    const auto value = mrpt::typemeta::TEnumType<T>::value2name(v);
    c.write(s, key, value, MRPT_SAVE_NAME_PADDING(), MRPT_SAVE_VALUE_PADDING(),
            comment.empty() ? names : names + ": " + comment);
  } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
    std::string words;
    for (const auto& w : v) words += (words.empty() ? "" : " ") + w;
    write(c, s, key, words, comment);
  } else if constexpr (std::is_same_v<T, std::string>) {
    // MRPT would read the comment after an empty value as the value ("key = // ..."), so an
    // empty text is saved bare.
    if (v.empty())
      c.write(s, key, v);
    else
      c.write(s, key, v, MRPT_SAVE_NAME_PADDING(), MRPT_SAVE_VALUE_PADDING(), comment);
  } else {
    c.write(s, key, v, MRPT_SAVE_NAME_PADDING(), MRPT_SAVE_VALUE_PADDING(), comment);
  }
}

/** "[section] key = value: why (comment)". */
[[noreturn]] void failCheck(const std::string& section, const std::string& key,
                            const std::string& value, const std::string& why,
                            const std::string& comment);
std::string show(double v);
std::string show(const std::string& v);
std::string show(const std::vector<std::string>& v);

/** The comment a check adds in front of the saved comment ("a|b|c" for OneOf). */
inline std::string commentOf(const OneOf& o) {
  std::string s;
  for (const auto& n : o.names) s += (s.empty() ? "" : "|") + n;
  return s;
}
template <class C>
std::string commentOf(const C&) {
  return "";
}

/** Reads each declared key present in the section, strictly typed. */
struct Loader {
  const mrpt::config::CConfigFileBase& c;
  std::string s;
  template <class T, class... Checks>
  void operator()(T& field, const char* key, const char*, const Checks&...) {
    if (!c.keyExists(s, key)) return;
    T value = field;
    parse(rawValue(c, s, key), value, s, key);
    field = value;
  }
  template <class P>
  void section(P& sub, const std::string& name) {
    sub.loadKeys(c, name);  // the parent's validate() checks it, once
  }
  template <class P>
  void merge(P& sub) {
    P::declare(sub, *this);
  }
};

/** Writes each key with its value and comment. */
struct Saver {
  mrpt::config::CConfigFileBase& c;
  std::string s;
  template <class T, class... Checks>
  void operator()(const T& field, const char* key, const char* comment, const Checks&... checks) {
    std::string full;
    for (const auto& part : {commentOf(checks)..., std::string(comment)})
      if (!part.empty()) full += (full.empty() ? "" : ": ") + part;
    write(c, s, key, field, full);
  }
  template <class P>
  void section(const P& sub, const std::string& name) {
    sub.saveToConfigFile(c, name);
  }
  template <class P>
  void merge(const P& sub) {
    P::declare(sub, *this);
  }
};

/** Applies each key's checks to its current value. */
struct Checker {
  std::string s;
  template <class T, class... Checks>
  void operator()(const T& field, [[maybe_unused]] const char* key,
                  [[maybe_unused]] const char* comment, const Checks&... checks) {
    (check(field, key, comment, checks), ...);
  }
  template <class T, class C>
  void check(const T& field, const char* key, const char* comment, const C& rule) const {
    const auto why = rule.why(field);
    if (!why.empty()) failCheck(s, key, show(field), why, comment);
  }
  template <class P>
  void section(const P& sub, const std::string& name) {
    sub.validate(name);
  }
  template <class P>
  void merge(const P& sub) {
    P::declare(sub, *this);
    sub.checkTogether(s);
  }
};

/** Collects the keys of the struct's own section; a key declared twice is a programming error
 * (std::logic_error). */
struct Lister {
  std::vector<std::string> keys;
  template <class T, class... Checks>
  void operator()(const T&, const char* key, const char*, const Checks&...) {
    add(key);
  }
  template <class P>
  void section(const P&, const std::string&) {}
  template <class P>
  void merge(const P& sub) {
    P::declare(sub, *this);
  }
  void add(const std::string& key);
};

}  // namespace params_detail

/** Base of every params struct: loadFromConfigFile() / saveToConfigFile() and the checks, derived
 * from `Self::declare()`. See the file comment. */
template <class Self>
struct Params : public mrpt::config::CLoadableOptions {
  /** Rejects unknown keys, reads the declared keys present (strictly typed; absent keys keep
   * their value), loads the sub-sections and validates. Throws ConfigError naming section and
   * key. */
  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override {
    loadKeys(c, s);
    validate(s);
  }

  /** Rejects unknown keys and reads the declared keys present (strictly typed), sub-sections
   * included, without the range checks (validate() does those). */
  void loadKeys(const mrpt::config::CConfigFileBase& c, const std::string& s) {
    rejectUnknownKeys(c, s, keyNames());
    params_detail::Loader loader{c, s};
    Self::declare(self(), loader);
  }

  /** Writes every declared key of `s`, then the sub-sections. */
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override {
    params_detail::Saver saver{c, s};
    Self::declare(self(), saver);
  }

  /** Throws ConfigError "[s] key = value: must be ..." for a value outside its declared checks
   * or the struct's checkTogether() rules; sub-sections are checked too. For values set in code
   * (command-line overrides). */
  void validate(const std::string& s) const {
    params_detail::Checker checker{s};
    Self::declare(self(), checker);
    self().checkTogether(s);
  }

  /** The keys of the struct's own section (merged structs included), in declaration order. */
  std::vector<std::string> keyNames() const {
    params_detail::Lister lister;
    Self::declare(self(), lister);
    return lister.keys;
  }

  /** Rules between several fields; a struct that has some hides this. */
  void checkTogether(const std::string&) const {}

 private:
  Self& self() { return static_cast<Self&>(*this); }
  const Self& self() const { return static_cast<const Self&>(*this); }
};

}  // namespace hrgbd
