#pragma once
// The one place where an app's errors are caught: a one-line message on
// stderr and exit code 1 (2 for command-line mistakes).

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <exception>
#include <functional>
#include <iostream>
#include <string>

namespace omnirange::app
{
inline std::string oneLine(std::string s)
{
	for (auto& c : s)
		if (c == '\n' || c == '\r') c = ' ';
	return s;
}

/** Thrown by parseArgs() to end the program with a code (after --help: 0). */
struct ExitRequest
{
	int code;
};

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

/** Parses the command line; on --help/--version or an error, ends the
 * program through runApp() with code 0 or 2. */
inline void parseArgs(TCLAP::CmdLine& cmd, int argc, char** argv)
{
	OneLineOutput out;
	cmd.setOutput(&out);
	const bool ok = cmd.parse(argc, argv);
	cmd.setOutput(nullptr);
	if (!ok) throw ExitRequest{out.failed ? 2 : 0};
}

inline int runApp(const std::string& name, const std::function<int()>& body)
{
	try
	{
		return body();
	}
	catch (const ExitRequest& e)
	{
		return e.code;
	}
	catch (const std::exception& e)
	{
		std::cerr << name << ": error: " << oneLine(e.what()) << "\n";
		return 1;
	}
}

}  // namespace omnirange::app
