#include "omnirange_apps/CommandLine.h"

#include <omnirange/core/Rangefinder.h>
#include <omnirange/io/MemoryLimit.h>
#include <omnirange/config/Output.h>
#include <omnirange/config/ErrorText.h>
#include <omnirange/config/Activity.h>


#include <opencv2/core.hpp>
#include <opencv2/core/utils/logger.hpp>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace omnirange::app
{
namespace
{
/** TCLAP output whose failure message is one line instead of the usage. */
class OneLineOutput : public TCLAP::StdOutput
{
   public:
	void failure(TCLAP::CmdLineInterface& c, TCLAP::ArgException& e) override
	{
		std::cerr << c.getProgramName() << ": error: " << oneLine(e.error())
				  << (e.argId().empty() || e.argId() == " " ? "" : " (" + oneLine(e.argId()) + ")")
				  << "; see --help\n";
		failed = true;
	}
	bool failed{false};
};
}  // namespace

VerbosityArgs::VerbosityArgs(TCLAP::CmdLine& cmd)
	: quiet("q", "quiet", "errors only: no progress, options or summary", cmd),
	  verbose("v", "verbose", "debug output", cmd)
{
}

RangefinderIniArgs::RangefinderIniArgs(TCLAP::CmdLine& cmd, const std::string& what, bool required)
	: ini("c", "config", "ini with " + what, required, "", "INI", cmd),
	  section("s", "section", "its section with the rangefinder's keys", false, kRangefinderSection, "NAME", cmd)
{
}

ForceArg::ForceArg(TCLAP::CmdLine& cmd)
	: force("", "force",
			"replace an existing output (file or folder) that this program did not write; never an input", cmd)
{
}

mrpt::system::VerbosityLevel VerbosityArgs::level()
{
	if (quiet.getValue()) return mrpt::system::LVL_ERROR;
	return verbose.getValue() ? mrpt::system::LVL_DEBUG : mrpt::system::LVL_INFO;
}

std::string requiredPath(TCLAP::ValueArg<std::string>& arg)
{
	if (arg.getValue().empty())
		throw std::invalid_argument((arg.getFlag().empty() ? "--" + arg.getName() : "-" + arg.getFlag()) +
									" names no file or folder");
	return arg.getValue();
}

std::string optionalPath(TCLAP::ValueArg<std::string>& arg)
{
	return arg.isSet() ? requiredPath(arg) : arg.getValue();
}

std::string prefixPath(TCLAP::ValueArg<std::string>& arg, const std::string& example)
{
	const std::string given = optionalPath(arg);
	if (given.empty()) return given;
	const std::string prefix = outputPath(given);
	std::error_code ec;  // a folder this user cannot look in: the output rule says so, with the reason
	if (given.back() == '/' || prefix == "." || prefix == ".." || std::filesystem::is_directory(prefix, ec))
		throw std::invalid_argument((arg.getFlag().empty() ? "--" + arg.getName() : "-" + arg.getFlag()) + " '" + given +
									"' is a folder; give a prefix for the files, e.g. '" +
									(std::filesystem::path(prefix) / example).string() + "'");
	return given;
}

void parseArgs(TCLAP::CmdLine& cmd, int argc, const char* const* argv)
{
	OneLineOutput out;
	cmd.setOutput(&out);
	const bool ok = cmd.parse(argc, const_cast<const char**>(argv));
	cmd.setOutput(nullptr);
	if (!ok) throw ExitRequest{out.failed ? 2 : 0};
}

std::string errorText(const std::exception& e)
{
	if (const auto* cv_error = dynamic_cast<const cv::Exception*>(&e))
		return oneLine("OpenCV: " + cv_error->err + (cv_error->func.empty() ? "" : " (in " + cv_error->func + ")"));
	return errorInOneLine(e.what());
}

namespace
{
/** A relative path met a removed working folder: std::filesystem's text
 * ("cannot make absolute path") would not say so. */
bool workingFolderGone(const std::exception& e)
{
	char here[4096];
	return dynamic_cast<const std::filesystem::filesystem_error*>(&e) != nullptr && ::getcwd(here, sizeof here) == nullptr &&
		   errno == ENOENT;
}
}  // namespace

int runApp(const std::string& name, const std::function<void()>& body)
{
	// OpenCV's own log lines (a cut image, a codec's complaint) would make an
	// error several lines; what fails is reported once, naming the file.
	cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
	activity::nameExitsAs(name);
	// Each line out as it is made: a run interrupted with its output in a file or a pipe keeps what it said.
	std::setvbuf(stdout, nullptr, _IOLBF, 0);
	// Past a file-size limit (ulimit -f) a write then fails with EFBIG, which
	// the writers report naming the file, rather than the signal killing the
	// run without a word.
	std::signal(SIGXFSZ, SIG_IGN);
	capAddressSpaceAtHalfTheMemory();
	// However the body ends, the run has ended: an exit() after it is no library's doing.
	struct Ended
	{
		~Ended() { activity::set(""); }
	} ended;
	try
	{
		body();
		return 0;
	}
	catch (const ExitRequest& e)
	{
		return e.code;
	}
	catch (const std::bad_alloc&)
	{
		const std::string doing = activity::current();
		std::cerr << name << ": error: out of memory" << (doing.empty() ? "" : " while " + oneLine(doing)) << "\n";
		return 1;
	}
	catch (const std::exception& e)
	{
		std::cerr << name << ": error: " << (workingFolderGone(e) ? "the working folder no longer exists: change to one that does" : errorText(e)) << "\n";
		return 1;
	}
}

RangefinderParams loadRangefinderIni(const std::string& file, const std::string& section,
									 mrpt::system::COutputLogger& log)
{
	const RangefinderParams p = RangefinderParams::loadFromFile(file, section);
	log.logStr(mrpt::system::LVL_INFO, file + " [" + section + "], unlike the defaults: " + p.changes());
	log.logStr(mrpt::system::LVL_DEBUG, "every option:\n" + p.asIni());
	return p;
}

Progress* progressAt(mrpt::system::VerbosityLevel level, Progress& progress)
{
	return level <= mrpt::system::LVL_INFO ? &progress : nullptr;
}

}  // namespace omnirange::app
