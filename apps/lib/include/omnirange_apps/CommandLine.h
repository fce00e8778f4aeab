#pragma once
// What every app's command line shares: parsing with TCLAP into an options
// struct, the verbosity flags, and the one place where an app's errors are
// caught: a one-line message on stderr and exit code 1 (2 for command-line
// mistakes, 0 after --help).

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/system/COutputLogger.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace omnirange
{
struct RangefinderParams;
class Progress;
}

namespace omnirange::app
{
/** Thrown by parseArgs() to end the program with a code (after --help: 0). */
struct ExitRequest
{
	int code;
};

/** -q/--quiet and -v/--verbose, added to a command line. */
struct VerbosityArgs
{
	explicit VerbosityArgs(TCLAP::CmdLine& cmd);
	/** LVL_ERROR when quiet, LVL_DEBUG when verbose, else LVL_INFO. */
	mrpt::system::VerbosityLevel level();

	TCLAP::SwitchArg quiet, verbose;
};

/** --force, added to a command line: replace an output that this program
 * did not write (the output rule, config/Output.h; never an input). */
struct ForceArg
{
	explicit ForceArg(TCLAP::CmdLine& cmd);
	bool value() { return force.getValue(); }

	TCLAP::SwitchArg force;
};

/** -c/--config INI and -s/--section NAME, added to a command line: the ini
 * an app reads its [rangefinder] from; `what` says what the app takes from it. */
struct RangefinderIniArgs
{
	RangefinderIniArgs(TCLAP::CmdLine& cmd, const std::string& what, bool required);

	TCLAP::ValueArg<std::string> ini, section;
};

/** Options declared once each: the flags, the help and the field an option
 * fills, whose value before parsing is the option's default; fill() copies
 * every value given into its field after parseArgs(). Paths and options
 * that need checking beside others stay plain TCLAP arguments. */
class BoundArgs
{
   public:
	explicit BoundArgs(TCLAP::CmdLine& cmd) : cmd_(cmd) {}

	template <class T>
	TCLAP::ValueArg<T>& value(const std::string& flag, const std::string& name, const std::string& help, T& field,
							  const std::string& type)
	{
		auto arg = std::make_unique<TCLAP::ValueArg<T>>(flag, name, help, false, field, type, cmd_);
		auto& given = *arg;
		fill_.push_back([&given, &field] { field = given.getValue(); });
		args_.push_back(std::move(arg));
		return given;
	}
	/** An option read as a string and turned into its field's type by `parse` (an enum's name). */
	template <class T, class Parse>
	TCLAP::ValueArg<std::string>& named(const std::string& name, const std::string& help, T& field,
										const std::string& as_text, Parse parse, const std::string& type)
	{
		auto arg = std::make_unique<TCLAP::ValueArg<std::string>>("", name, help, false, as_text, type, cmd_);
		auto& given = *arg;
		fill_.push_back([&given, &field, parse] { field = parse(given.getValue()); });
		args_.push_back(std::move(arg));
		return given;
	}
	TCLAP::SwitchArg& flag(const std::string& name, const std::string& help, bool& field)
	{
		auto arg = std::make_unique<TCLAP::SwitchArg>("", name, help, cmd_, field);
		auto& given = *arg;
		fill_.push_back([&given, &field] { field = given.getValue(); });
		args_.push_back(std::move(arg));
		return given;
	}
	/** --omni-label, --laser-label and --max-dt: how a log's images pair with its laser scans. */
	void pairing(std::string& omni_label, std::string& laser_label, double& max_dt)
	{
		value("", "omni-label", "label of the images", omni_label, "LABEL");
		value("", "laser-label", "label of the laser scans", laser_label, "LABEL");
		value("", "max-dt", "largest time between an image and its scan [s]", max_dt, "S");
	}
	/** After parseArgs(): every bound field takes its option's value. */
	void fill() const
	{
		for (const auto& f : fill_) f();
	}

   private:
	TCLAP::CmdLine& cmd_;
	std::vector<std::unique_ptr<TCLAP::Arg>> args_;
	std::vector<std::function<void()>> fill_;
};

/** The value of a required path option; throws std::invalid_argument when
 * it is empty (`-o ''` would otherwise run every stage and then fail). */
std::string requiredPath(TCLAP::ValueArg<std::string>& arg);
/** The value of an optional path option: "" when not given; throws
 * std::invalid_argument when given empty (`--save-to ''` would be ignored). */
std::string optionalPath(TCLAP::ValueArg<std::string>& arg);

/** The value of a prefix option (PREFIX_pairs.csv, PREFIX.md): "" when not
 * given; throws std::invalid_argument when it names a folder ("out/", ".",
 * an existing folder), whose files would be hidden ("out/_pairs.csv"). */
std::string prefixPath(TCLAP::ValueArg<std::string>& arg, const std::string& example);

/** Parses the command line; on --help/--version or an error (reported on
 * one line of stderr), throws ExitRequest with code 0 or 2. */
void parseArgs(TCLAP::CmdLine& cmd, int argc, const char* const* argv);

/** An exception's text as one line: OpenCV's as its message and function
 * (no source path or version), MRPT's as its messages without the call
 * stack, any other with its line breaks made spaces. */
std::string errorText(const std::exception& e);

/** Runs `body`; returns 0, ExitRequest's code, or 1 after printing
 * "NAME: error: MESSAGE" on one line for any exception. */
int runApp(const std::string& name, const std::function<void()>& body);

/** The rangefinder's section of an ini file (over its base), with the file
 * named in errors; the options that differ from the defaults are logged on
 * one line at INFO, all of them at DEBUG. */
RangefinderParams loadRangefinderIni(const std::string& file, const std::string& section,
									 mrpt::system::COutputLogger& log);

/** `progress` when `level` shows progress (INFO or more), else nullptr. */
Progress* progressAt(mrpt::system::VerbosityLevel level, Progress& progress);

}  // namespace omnirange::app
