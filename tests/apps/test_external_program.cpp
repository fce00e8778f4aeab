// MRPT's programs are started with an argument vector in a working folder:
// a path or value with quotes, spaces or shell syntax reaches the program as
// it is, and nothing is ever run through a shell.
#include <omnirange_eval/ExternalProgram.h>

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>
#include <sstream>

namespace fs = std::filesystem;
using omnirange::eval::runProgram;

TEST(ExternalProgram, ArgumentsAndFolderReachTheProgramUnchanged)
{
	const fs::path dir = fs::temp_directory_path() / "omnirange_apps" / "bob's run; touch pwned";
	fs::remove_all(dir);
	fs::create_directories(dir);
	const std::string tricky = "a'b $(touch pwned2) \"c\"";
	runProgram({"sh", "-c", "pwd; printf '%s\\n' \"$1\"; read x || echo no-stdin", "sh", tricky}, dir.string(), "out.log");
	std::ifstream log(dir / "out.log");
	std::stringstream text;
	text << log.rdbuf();
	EXPECT_EQ(text.str(), dir.string() + "\n" + tricky + "\nno-stdin\n");
	EXPECT_FALSE(fs::exists(dir / "pwned"));
	EXPECT_FALSE(fs::exists(dir / "pwned2"));
}

TEST(ExternalProgram, FailureNamesTheProgramAndTheLogsLastLine)
{
	const fs::path dir = fs::temp_directory_path() / "omnirange_apps" / "failing";
	fs::create_directories(dir);
	try
	{
		runProgram({"sh", "-c", "echo first; echo 'the reason' >&2; exit 3"}, dir.string(), "fail.log");
		FAIL() << "a failing program must throw";
	}
	catch (const std::runtime_error& e)
	{
		const std::string what = e.what();
		EXPECT_NE(what.find("sh failed (exit code 3"), std::string::npos) << what;
		EXPECT_NE(what.find("the reason"), std::string::npos) << what;
	}
	EXPECT_THROW(runProgram({"no-such-program-here"}, dir.string(), "x.log"), std::runtime_error);
	// MRPT's programs end a failure with a prompt: the line before it is the cause.
	try
	{
		runProgram({"sh", "-c", "echo 'cannot write map.gz'; echo 'Press any key to continue...'; exit 255"}, dir.string(),
				   "mrpt.log");
		FAIL() << "a failing program must throw";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("): cannot write map.gz"), std::string::npos) << e.what();
	}
	// An MRPT exception: its message, not the last frame of the call stack printed after it.
	const std::string mrpt_block = "==== MRPT exception ====\nMessage:  ASSERT_GT_(decimation,0) failed with\ndecimation=0\n\n"
								   "Location: CPointsMap.cpp:289\nCall stack backtrace:\n[0 ]     0x7f22ffe9184c \n"
								   "[9 ]     0x5613cbfae321 \nPress any key to continue...\n";
	std::ofstream(dir / "block.txt") << mrpt_block;
	try
	{
		runProgram({"sh", "-c", "cat block.txt; exit 255"}, dir.string(), "mrpt-block.log");
		FAIL() << "a failing program must throw";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("): ASSERT_GT_(decimation,0) failed with decimation=0"), std::string::npos)
			<< e.what();
		EXPECT_EQ(std::string(e.what()).find("0x"), std::string::npos) << e.what();
	}
	// A log that cannot be made is said as such, and the program is not started.
	try
	{
		runProgram({"sh", "-c", "touch started"}, dir.string(), "no-such-folder/x.log");
		FAIL() << "a log that cannot be made must throw";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("cannot create the log"), std::string::npos) << e.what();
		EXPECT_NE(std::string(e.what()).find("No such file"), std::string::npos) << e.what();
	}
	EXPECT_FALSE(fs::exists(dir / "started"));
}

TEST(ExternalProgram, ARunKilledOutrightTakesItsProgramWithIt)
{
	const fs::path dir = fs::temp_directory_path() / "omnirange_apps" / "orphan";
	fs::remove_all(dir);
	fs::create_directories(dir);
	// The child stands for a run: it starts a program that writes its pid and
	// sleeps, and is then killed with SIGKILL, so no handler of its runs.
	const pid_t run = ::fork();
	ASSERT_GE(run, 0);
	if (run == 0)
	{
		try
		{
			runProgram({"sh", "-c", "echo $$ > pid.txt; exec sleep 60"}, dir.string(), "sleep.log");
		}
		catch (...)
		{
		}
		::_exit(0);
	}
	const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
	pid_t program = 0;
	while (program == 0 && std::chrono::steady_clock::now() < deadline)
	{
		std::ifstream f(dir / "pid.txt");
		if (!(f >> program)) program = 0;
		std::this_thread::sleep_for(std::chrono::milliseconds(20));
	}
	ASSERT_GT(program, 0) << "the program never started";
	::kill(run, SIGKILL);
	::waitpid(run, nullptr, 0);
	bool gone = false;
	while (!gone && std::chrono::steady_clock::now() < deadline)
	{
		// Gone, or a zombie no one has reaped yet (its state in /proc is Z).
		std::ifstream stat("/proc/" + std::to_string(program) + "/stat");
		std::string pid, name, state;
		gone = !(stat >> pid >> name >> state) || state == "Z";
		if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(20));
	}
	EXPECT_TRUE(gone) << "pid " << program << " outlived the run";
	if (!gone) ::kill(program, SIGKILL);
}
