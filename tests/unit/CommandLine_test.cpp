// The apps' command-line layer: --help / --version answer and exit 0 without running the work,
// refused command lines exit 2 with "<app>: error:" and run nothing, and an exception from the
// work exits 1.
#include "rgbd_cli/CommandLine.h"

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace demo {
enum class Mode { Fast, Exact };
}
MRPT_ENUM_TYPE_BEGIN(demo::Mode)
MRPT_FILL_ENUM_CUSTOM_NAME(demo::Mode::Fast, "fast");
MRPT_FILL_ENUM_CUSTOM_NAME(demo::Mode::Exact, "exact");
MRPT_ENUM_TYPE_END()

namespace {

/** A small app with one option of each kind the apps use. TCLAP parses a command line once, so
 * each run needs a fresh Demo. */
struct Demo {
  /** Runs the app with `args` (after the program name); returns the exit code. */
  int run(
      std::vector<std::string> args, const std::function<void()>& work = [] {}) {
    args.insert(args.begin(), "/some/path/demo");
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    return cmd.run(static_cast<int>(argv.size()), argv.data(), [&] {
      ran = true;
      work();
    });
  }

  std::ostringstream out, err;
  hrgbd::CommandLine cmd{"demo", "a test app", out, err};
  TCLAP::ValueArg<int> count{"n", "count", "how many (0 = all)", false, 0, cmd.atLeast(0, "N"),
                             cmd};
  TCLAP::ValueArg<double> delta{"", "delta", "interval [s]", false, 1.0, cmd.above(0.0, "SECONDS"),
                                cmd};
  TCLAP::ValueArg<double> rate{"", "rate", "speed", false, 1.0, cmd.atLeast(0.0, "R"), cmd};
  TCLAP::ValueArg<double> hold{"", "hold", "negative = forever", false, -1, cmd.finite("S"), cmd};
  TCLAP::ValueArg<std::string> mode{"m", "mode", "the mode", false, "", cmd.oneOf<demo::Mode>(),
                                    cmd};
  TCLAP::ValueArg<std::string> colour{
      "", "colour", "a colour", false, "red", cmd.oneOf({"red", "green"}), cmd};
  bool ran = false;
};

TEST(CommandLine, ValidArgumentsRunTheWorkAndExitZero) {
  Demo d;
  EXPECT_EQ(d.run({"-n", "3", "--delta", "0.5", "--rate", "0", "--hold", "-2.5", "-m", "exact",
                   "--colour", "green"}),
            hrgbd::kExitSuccess);
  EXPECT_TRUE(d.ran);
  EXPECT_EQ(d.count.getValue(), 3);
  EXPECT_DOUBLE_EQ(d.delta.getValue(), 0.5);
  EXPECT_DOUBLE_EQ(d.rate.getValue(), 0.0);
  EXPECT_DOUBLE_EQ(d.hold.getValue(), -2.5);
  EXPECT_EQ(d.mode.getValue(), "exact");
  EXPECT_EQ(d.colour.getValue(), "green");
  EXPECT_TRUE(d.err.str().empty()) << d.err.str();
}

TEST(CommandLine, DefaultsAreNotCheckedAgainstTheirConstraint) {
  Demo d;  // --mode "" is not a mode: "" means "not given"
  EXPECT_EQ(d.run({}), hrgbd::kExitSuccess);
  EXPECT_TRUE(d.ran);
  EXPECT_EQ(d.mode.getValue(), "");
}

TEST(CommandLine, HelpPrintsUsageWithAllowedValuesAndRunsNothing) {
  Demo d;
  EXPECT_EQ(d.run({"-n", "3", "--help"}), hrgbd::kExitSuccess);
  EXPECT_FALSE(d.ran);
  const auto help = d.out.str();
  EXPECT_NE(help.find("USAGE"), std::string::npos) << help;
  EXPECT_NE(help.find("demo: a test app"), std::string::npos) << help;
  EXPECT_NE(help.find("<fast|exact>"), std::string::npos) << help;
  EXPECT_NE(help.find("<red|green>"), std::string::npos) << help;
  EXPECT_NE(help.find("--count <N>"), std::string::npos) << help;
  EXPECT_EQ(help.find("/some/path"), std::string::npos) << "the app's name, not argv[0]";
  EXPECT_TRUE(d.err.str().empty()) << d.err.str();
}

TEST(CommandLine, VersionPrintsNameAndVersionAndRunsNothing) {
  Demo d;
  EXPECT_EQ(d.run({"--version"}), hrgbd::kExitSuccess);
  EXPECT_FALSE(d.ran);
  EXPECT_EQ(d.out.str().rfind("demo ", 0), 0u) << d.out.str();
  EXPECT_GT(d.out.str().size(), std::string("demo \n").size());
}

TEST(CommandLine, UnknownOptionIsRefusedWithAHint) {
  Demo d;
  EXPECT_EQ(d.run({"--mdoe", "fast"}), hrgbd::kExitUsageError);
  EXPECT_FALSE(d.ran);
  const auto e = d.err.str();
  EXPECT_EQ(e.rfind("demo: error: --mdoe", 0), 0u) << e;
  EXPECT_NE(e.find("demo --help"), std::string::npos) << e;
  EXPECT_TRUE(d.out.str().empty()) << d.out.str();
}

TEST(CommandLine, IntegersMustBeWholeNumbers) {
  for (const std::string bad : {"abc", "1.5", "3x", ""}) {
    Demo d;
    EXPECT_EQ(d.run({"-n", bad}), hrgbd::kExitUsageError) << bad;
    EXPECT_FALSE(d.ran) << bad;
    EXPECT_NE(d.err.str().find("--count"), std::string::npos) << d.err.str();
  }
}

TEST(CommandLine, RangesAreChecked) {
  Demo a, b, c, ok;
  EXPECT_EQ(a.run({"-n", "-1"}), hrgbd::kExitUsageError);
  EXPECT_NE(a.err.str().find("must be >= 0"), std::string::npos) << a.err.str();
  EXPECT_EQ(b.run({"--delta", "0"}), hrgbd::kExitUsageError);
  EXPECT_NE(b.err.str().find("must be > 0"), std::string::npos) << b.err.str();
  EXPECT_EQ(c.run({"--rate", "-0.5"}), hrgbd::kExitUsageError);
  EXPECT_FALSE(a.ran || b.ran || c.ran);
  EXPECT_EQ(ok.run({"-n", "0", "--delta", "1e-9", "--rate", "0"}), hrgbd::kExitSuccess);
  EXPECT_TRUE(ok.ran);
}

TEST(CommandLine, RealsMustBeFinite) {
  for (const std::string bad : {"nan", "NaN", "inf", "-inf", "1e999", "abc", "0.5s"}) {
    for (const std::string option : {"--delta", "--hold"}) {
      Demo d;
      EXPECT_EQ(d.run({option, bad}), hrgbd::kExitUsageError) << option << " " << bad;
      EXPECT_FALSE(d.ran);
    }
  }
}

TEST(CommandLine, NamesOutsideTheDeclarationAreRefused) {
  Demo a, b;
  EXPECT_EQ(a.run({"-m", "slow"}), hrgbd::kExitUsageError);
  EXPECT_NE(a.err.str().find("must be one of fast|exact"), std::string::npos) << a.err.str();
  EXPECT_EQ(b.run({"--colour", "Red"}), hrgbd::kExitUsageError);
  EXPECT_FALSE(a.ran || b.ran);
}

TEST(CommandLine, MissingValueIsRefused) {
  Demo d;
  EXPECT_EQ(d.run({"-n"}), hrgbd::kExitUsageError);
  EXPECT_FALSE(d.ran);
}

TEST(CommandLine, ExceptionFromTheWorkIsARuntimeError) {
  Demo d;
  EXPECT_EQ(d.run({}, [] { throw std::runtime_error("cannot open x.rawlog"); }),
            hrgbd::kExitRuntimeError);
  EXPECT_TRUE(d.ran);
  EXPECT_EQ(d.err.str(), "demo: error: cannot open x.rawlog\n");
}

TEST(CommandLine, UsageErrorFromTheWorkExitsTwoWithTheHint) {
  Demo d;
  EXPECT_EQ(d.run({}, [] { throw hrgbd::UsageError("give --rawlog and/or --tum"); }),
            hrgbd::kExitUsageError);
  EXPECT_EQ(d.err.str().rfind("demo: error: give --rawlog and/or --tum\n", 0), 0u) << d.err.str();
  EXPECT_NE(d.err.str().find("demo --help"), std::string::npos) << d.err.str();
}

TEST(CommandLine, MissingPositionalArgumentIsRefused) {
  std::ostringstream out, err;
  hrgbd::CommandLine cmd("pos", "positional arguments", out, err);
  TCLAP::UnlabeledValueArg<std::string> in("input", "input file", true, "", "IN", cmd);
  const char* argv[] = {"pos"};
  bool ran = false;
  EXPECT_EQ(cmd.run(1, argv, [&] { ran = true; }), hrgbd::kExitUsageError);
  EXPECT_FALSE(ran);
  EXPECT_EQ(err.str().rfind("pos: error: ", 0), 0u) << err.str();
}

TEST(CommandLine, UnknownOptionIsNotTakenAsAPositionalArgument) {
  const auto run = [](std::vector<const char*> argv, std::vector<std::string>* paths) {
    std::ostringstream out, err;
    hrgbd::CommandLine cmd("multi", "positional paths", out, err);
    TCLAP::ValueArg<int> n("n", "count", "how many", false, 0, cmd.atLeast(0, "N"), cmd);
    TCLAP::UnlabeledMultiArg<std::string> in("paths", "input paths", false, "PATH", cmd);
    return cmd.run(static_cast<int>(argv.size()), argv.data(), [&] { *paths = in.getValue(); });
  };
  std::vector<std::string> paths;
  EXPECT_EQ(run({"multi", "a", "--unknown", "b"}, &paths), hrgbd::kExitUsageError);
  EXPECT_TRUE(paths.empty());
  EXPECT_EQ(run({"multi", "-n", "2", "a", "b"}, &paths), hrgbd::kExitSuccess);
  EXPECT_EQ(paths, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(run({"multi", "a", "--", "-odd-name"}, &paths), hrgbd::kExitSuccess);
  EXPECT_EQ(paths, (std::vector<std::string>{"a", "-odd-name"}));
}

TEST(CommandLine, EnumValuesFollowTheDeclaration) {
  EXPECT_EQ(hrgbd::enumNameList<demo::Mode>(), (std::vector<std::string>{"fast", "exact"}));
}

}  // namespace
