#include "rgbd_cli/CommandLine.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <list>
#include <sstream>
#include <type_traits>

#include "rgbd_core/Interrupt.h"

namespace hrgbd {

/** TCLAP's printer, remembering what parse() did: TCLAP prints the help or an error and returns
 * false for both, so the outcome is recorded here. Errors are kept, not printed. */
class CommandLine::Output : public TCLAP::StdOutput {
 public:
  explicit Output(std::ostream& out) : TCLAP::StdOutput(out) {}
  void usage(TCLAP::CmdLineInterface& c) override {
    printed = true;
    TCLAP::StdOutput::usage(c);
  }
  void version(TCLAP::CmdLineInterface& c) override {
    printed = true;
    m_my_output << c.getProgramName() << " " << c.getVersion() << "\n";
  }
  void failure(TCLAP::CmdLineInterface&, TCLAP::ArgException& e) override {
    // argId() is "Argument: -n (--max-frames)", "Argument: --unknown" or "undefined argument".
    std::string id = e.argId();
    const std::string prefix = "Argument: ";
    if (id.rfind(prefix, 0) != 0) {
      error = e.error();
      return;
    }
    id = id.substr(prefix.size());
    if (const auto open = id.find("(--"); open != std::string::npos && id.back() == ')')
      id = id.substr(open + 1, id.size() - open - 2);  // the long name alone
    error = id + ": " + e.error();
  }
  bool printed = false;  //!< --help or --version was answered
  std::string error;     //!< the parse error, if any
};

namespace {

/** value >= min (or > min when `strict`); reals must also be finite. */
template <class T>
class Bound : public TCLAP::Constraint<T> {
 public:
  Bound(T min, bool strict, std::string type) : m_min(min), m_strict(strict), m_type(type) {}
  std::string description() const override {
    if (m_min == std::numeric_limits<T>::lowest()) return "must be a finite number";
    std::ostringstream s;
    s << "must be " << (m_strict ? "> " : ">= ") << m_min;
    return s.str();
  }
  std::string shortID() const override { return m_type; }
  bool check(const T& v) const override {
    if constexpr (std::is_floating_point_v<T>)
      if (!std::isfinite(v)) return false;
    return m_strict ? v > m_min : v >= m_min;
  }

 private:
  T m_min;
  bool m_strict;
  std::string m_type;
};

/** The value is one of a list of names. */
class OneOf : public TCLAP::Constraint<std::string> {
 public:
  explicit OneOf(const std::vector<std::string>& allowed) : m_allowed(allowed) {
    for (const auto& a : allowed) m_names += (m_names.empty() ? "" : "|") + a;
  }
  std::string description() const override { return "must be one of " + m_names; }
  std::string shortID() const override { return m_names; }
  bool check(const std::string& v) const override {
    return std::find(m_allowed.begin(), m_allowed.end(), v) != m_allowed.end();
  }

 private:
  std::vector<std::string> m_allowed;
  std::string m_names;
};

/** Stores `c` in `owner` and returns it. */
template <class C>
C* keep(std::vector<std::shared_ptr<const void>>& owner, std::shared_ptr<C> c) {
  owner.push_back(c);
  return c.get();
}

/** Whether option `a` is a `To`. */
template <class To>
bool is(const TCLAP::Arg* a) {
  return dynamic_cast<const To*>(a) != nullptr;
}

/** The two things TCLAP lets through: an unknown "-x" where a positional argument may stand
 * (unlabeled arguments take any word, so `rgbd-benchmark --unknown` would run the benchmark on a
 * sequence named "--unknown"), and "" as a number (TCLAP reads nothing and keeps the default, so
 * `-n ""` would mean `-n 0`). Returns the error, or "" when there is none. */
std::string precheck(const std::list<TCLAP::Arg*>& options, const std::vector<const char*>& args) {
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string word = args[i];
    if (word == "--") break;  // the rest is positional
    const TCLAP::Arg* option = nullptr;
    for (const TCLAP::Arg* a : options)
      if (!is<TCLAP::UnlabeledValueArg<std::string>>(a) &&
          !is<TCLAP::UnlabeledMultiArg<std::string>>(a) && a->argMatches(word))
        option = a;
    if (!option) {
      if (word.size() > 1 && word[0] == '-') return word + ": unknown option";
      continue;
    }
    if (!option->isValueRequired() || ++i == args.size()) continue;
    if (*args[i] == '\0' &&
        (is<TCLAP::ValueArg<int>>(option) || is<TCLAP::ValueArg<double>>(option)))
      return "--" + option->getName() + ": an empty value is not a number";
  }
  return "";
}

}  // namespace

CommandLine::CommandLine(const std::string& app, const std::string& description, std::ostream& out,
                         std::ostream& err)
    : TCLAP::CmdLine(app + ": " + description, ' ', HRGBD_VERSION),
      m_app(app),
      m_err(err),
      m_output(std::make_unique<Output>(out)) {
  // TCLAP's own StdOutput, which setOutput() would leak: MRPT's bundled TCLAP (the one this
  // builds against, <mrpt/3rdparty/tclap>) does not delete it there, unlike upstream 1.2.x.
  delete getOutput();
  setOutput(m_output.get());
}

CommandLine::~CommandLine() = default;

int CommandLine::run(int argc, const char* const* argv, const std::function<void()>& work) {
  // Each line of stdout as it comes, into a pipe or file too (a log read while the app runs, or
  // after it was killed); stderr is unbuffered anyway.
  std::setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);
  // The app's name, not argv[0]'s path, in the usage text.
  std::vector<const char*> args(argv, argv + argc);
  if (args.empty()) args.push_back(nullptr);
  args[0] = m_app.c_str();
  m_output->printed = false;
  m_output->error.clear();
  if (const auto e = precheck(getArgList(), args); !e.empty()) return refuse(e);
  if (!parse(static_cast<int>(args.size()), args.data())) {
    if (m_output->printed && m_output->error.empty()) return kExitSuccess;
    return refuse(m_output->error.empty() ? "invalid command line" : m_output->error);
  }
  installInterruptHandlers();  // Ctrl-C: the outputs not complete are removed, then 130
  try {
    work();
    return kExitSuccess;
  } catch (const Interrupted& e) {
    m_err << "\n" << m_app << ": " << e.what() << ": stopped";
    const auto lost = notWritten();
    if (lost.empty()) m_err << "; every output not complete was left unwritten\n";
    for (std::size_t k = 0; k < lost.size(); ++k)
      m_err << (k == 0 ? "; not written: " : ", ") << lost[k] << (k + 1 == lost.size() ? "\n" : "");
    return e.exitCode();
  } catch (const UsageError& e) {
    return refuse(e.what());
  } catch (const std::exception& e) {
    m_err << m_app << ": error: " << e.what() << "\n";
    return kExitRuntimeError;
  } catch (...) {
    m_err << m_app << ": error: unknown exception\n";
    return kExitRuntimeError;
  }
}

int CommandLine::refuse(const std::string& what) const {
  m_err << m_app << ": error: " << what << "\nTry '" << m_app << " --help' for the options.\n";
  return kExitUsageError;
}

TCLAP::Constraint<int>* CommandLine::atLeast(int min, const std::string& type) {
  return keep(m_constraints, std::make_shared<Bound<int>>(min, false, type));
}

TCLAP::Constraint<double>* CommandLine::atLeast(double min, const std::string& type) {
  return keep(m_constraints, std::make_shared<Bound<double>>(min, false, type));
}

TCLAP::Constraint<double>* CommandLine::above(double min, const std::string& type) {
  return keep(m_constraints, std::make_shared<Bound<double>>(min, true, type));
}

TCLAP::Constraint<double>* CommandLine::finite(const std::string& type) {
  return keep(m_constraints,
              std::make_shared<Bound<double>>(std::numeric_limits<double>::lowest(), false, type));
}

TCLAP::Constraint<std::string>* CommandLine::oneOf(const std::vector<std::string>& allowed) {
  return keep(m_constraints, std::make_shared<OneOf>(allowed));
}

}  // namespace hrgbd
