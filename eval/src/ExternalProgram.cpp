#include "omnirange_eval/ExternalProgram.h"

#include <omnirange/io/MemoryLimit.h>
#include <omnirange/config/ErrorText.h>

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace omnirange::eval
{
namespace
{
/** What a failed program's log says of its failure: the messages of MRPT's exception block, else the
 * last line that is neither the closing prompt ("Press any key to continue...") nor a frame of a call
 * stack ("[9 ]     0x5613cbfae321"). */
std::string lastLine(const std::string& file)
{
	std::ifstream f(file);
	const std::string text((std::istreambuf_iterator<char>(f)), {});
	if (text.find("==== MRPT exception ====") != std::string::npos)
		if (const std::string m = mrptMessages(text); !m.empty()) return m;
	std::istringstream in(text);
	std::string line, last;
	const auto frame = [](const std::string& l) {
		const auto close = l.find(']');
		return !l.empty() && l[0] == '[' && close != std::string::npos && l.find_first_not_of("0123456789 ", 1) == close;
	};
	while (std::getline(in, line))
		if (line.find_first_not_of(" \t\r") != std::string::npos && line.rfind("Press any key", 0) != 0 &&
			line.rfind("Call stack", 0) != 0 && !frame(line))
			last = line;
	return last;
}

/** In the child, once its output is the log: says why in the log, whose last line the run quotes. */
[[noreturn]] void failInChild(const std::string& what, int code)
{
	const std::string why = what + ": " + std::strerror(errno) + "\n";
	(void)!::write(2, why.data(), why.size());
	::_exit(code);
}

/** In the child: redirect, change folder, exec; never returns. */
[[noreturn]] void execIn(const std::vector<char*>& args, const std::string& dir, int out, pid_t parent)
{
	// However the run ends (an error, Ctrl-C, kill -9), the kernel ends its
	// program: no observations2map or icp-slam is left writing into its folder.
	if (::prctl(PR_SET_PDEATHSIG, SIGTERM) != 0 || ::getppid() != parent) ::_exit(125);
	::signal(SIGXFSZ, SIG_DFL);  // the apps ignore it (CommandLine.cpp); MRPT's programs keep their default
	restoreAddressSpaceLimit();  // the apps cap their own (MemoryLimit.h), not MRPT's programs
	const int in = ::open("/dev/null", O_RDONLY);
	if (in < 0 || ::dup2(in, 0) < 0 || ::dup2(out, 1) < 0 || ::dup2(out, 2) < 0) ::_exit(126);
	if (::chdir(dir.c_str()) != 0) failInChild("cannot enter " + dir, 126);
	::execvp(args[0], args.data());
	failInChild(std::string("cannot start ") + args[0], 127);
}
}  // namespace

void runProgram(const std::vector<std::string>& argv, const std::string& dir, const std::string& log)
{
	if (argv.empty()) throw std::invalid_argument("runProgram: no program");
	std::vector<char*> args;
	for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
	args.push_back(nullptr);
	const std::string log_path = dir + "/" + log;
	// Opened here, so that a log that cannot be made is said as such (not as the program's failure).
	const int out = ::open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
	if (out < 0) throw std::runtime_error("cannot create the log '" + log_path + "' of " + argv[0] + ": " + std::strerror(errno));
	const pid_t parent = ::getpid();
	const pid_t pid = ::fork();
	if (pid < 0)
	{
		const std::string why = std::strerror(errno);
		::close(out);
		throw std::runtime_error("cannot start " + argv[0] + ": " + why);
	}
	if (pid == 0) execIn(args, dir, out, parent);
	::close(out);
	int status = 0;
	while (::waitpid(pid, &status, 0) < 0)
		if (errno != EINTR) throw std::runtime_error("lost " + argv[0] + ": " + std::strerror(errno));
	if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
	const std::string how = WIFEXITED(status) ? "exit code " + std::to_string(WEXITSTATUS(status))
											  : "signal " + std::to_string(WTERMSIG(status));
	throw std::runtime_error(argv[0] + " failed (" + how + ", log " + log_path + "): " + lastLine(log_path));
}

}  // namespace omnirange::eval
