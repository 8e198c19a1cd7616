#pragma once
/** \file CommandLine.h
 * The command-line layer shared by the apps: MRPT's bundled TCLAP with its outcome checked.
 * Every app's main declares its arguments on a CommandLine and hands its work to run():
 *   - `--help` / `--version` print to stdout and exit 0 without running the work;
 *   - a parse error or a value that fails its constraint prints "<app>: error: <what>" and a
 *     one-line hint to stderr and exits 2 without running the work;
 *   - an exception from the work prints "<app>: error: <what>" and exits 1 (UsageError, declared
 *     in rgbd_core/Config.h: 2). */
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/typemeta/TEnumType.h>

#include <functional>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "rgbd_core/Config.h"

namespace hrgbd {

/** Exit codes of every app. */
enum ExitCode : int {
  kExitSuccess = 0,       //!< the work ran, or --help / --version printed
  kExitRuntimeError = 1,  //!< the work threw (bad input file, configuration, sensor...)
  kExitUsageError = 2,    //!< the command line was refused; nothing ran
};

/** A TCLAP command line for one app. Declare the arguments after it (they register with it and
 * must not outlive it), then `return cmd.run(argc, argv, [&] { ...work... });` from main. */
class CommandLine : public TCLAP::CmdLine {
 public:
  /** `app`: the name used in messages and the usage text; `description`: one sentence for the
   * help. Usage, help and version go to `out`, errors to `err`. */
  CommandLine(const std::string& app, const std::string& description, std::ostream& out = std::cout,
              std::ostream& err = std::cerr);
  ~CommandLine() override;
  CommandLine(const CommandLine&) = delete;
  CommandLine& operator=(const CommandLine&) = delete;

  /** Parses `argv` and runs `work` only after a clean parse; returns the ExitCode. Besides
   * TCLAP's own errors, refuses an unknown `-x` / `--xyz` where a positional argument may stand
   * (TCLAP would take it as the positional value; "--" lets such a name through) and an empty
   * value for a number (TCLAP would keep the default). stdout is made line-buffered first, so
   * a pipe or log file gets each line as it is written. Call it once: TCLAP parses once. */
  int run(int argc, const char* const* argv, const std::function<void()>& work);

  /** Constraints for ValueArg / UnlabeledValueArg; this object owns them. `type` is the value's
   * name in the usage text (e.g. "N", "SECONDS"). A failed check is a parse error naming the
   * option and the rule. Reals must also be finite ("nan", "inf" and overflow already fail to
   * parse). */
  TCLAP::Constraint<int>* atLeast(int min, const std::string& type);        //!< value >= min
  TCLAP::Constraint<double>* atLeast(double min, const std::string& type);  //!< value >= min
  TCLAP::Constraint<double>* above(double min, const std::string& type);    //!< value > min
  TCLAP::Constraint<double>* finite(const std::string& type);               //!< any real
  /** The value must be one of `allowed`, which the usage text lists as `a|b|c`. */
  TCLAP::Constraint<std::string>* oneOf(const std::vector<std::string>& allowed);
  /** The value must name an E (enumNameList<E>()), as in the INI files. */
  template <class E>
  TCLAP::Constraint<std::string>* oneOf() {
    return oneOf(enumNameList<E>());
  }

 private:
  class Output;
  int refuse(const std::string& what) const;

  std::string m_app;
  std::ostream& m_err;
  std::unique_ptr<Output> m_output;
  std::vector<std::shared_ptr<const void>> m_constraints;
};

}  // namespace hrgbd
