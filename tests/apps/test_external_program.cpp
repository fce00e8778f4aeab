// MRPT's programs are started with an argument vector in a working folder:
// a path or value with quotes, spaces or shell syntax reaches the program as
// it is, and nothing is ever run through a shell.
#include <omnirange_eval/ExternalProgram.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
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
}
