// A full disk while a rawlog is written: the run fails with one line naming
// the file, nothing that looks whole is left, and an older file of that name
// stays. The disk fills through RLIMIT_FSIZE, in a child process.
#include <omnirange/io/RawlogWriter.h>

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace fs = std::filesystem;

namespace
{
/** In a child limited to `limit` bytes per file: write `objects` noisy scans
 * to `path`. Exit 0: it failed with a message naming the file; 1: it did not
 * fail; 2: it failed without naming the file. */
int writeWithLimit(const std::string& path, rlim_t limit, int objects)
{
	const pid_t pid = ::fork();
	if (pid == 0)
	{
		std::signal(SIGXFSZ, SIG_IGN);  // a write past the limit then fails with EFBIG, as on a full disk
		const rlimit r{limit, limit};
		::setrlimit(RLIMIT_FSIZE, &r);
		try
		{
			omnirange::RawlogWriter w(path, "omnirange-test");
			std::mt19937 rng(1);
			std::uniform_real_distribution<float> u(0.5f, 10.f);
			for (int k = 0; k < objects; ++k)
			{
				mrpt::obs::CObservation2DRangeScan s;
				s.timestamp = mrpt::Clock::fromDouble(1000.0 + k);  // the same bytes every run
				s.resizeScan(2000);
				for (int i = 0; i < 2000; ++i) s.setScanRange(i, u(rng)), s.setScanRangeValidity(i, true);
				w.write(s);
			}
			w.commit();
		}
		catch (const std::exception& e)
		{
			const std::string what = e.what();
			::_exit(what.find(path) != std::string::npos && what.find('\n') == std::string::npos ? 0 : 2);
		}
		::_exit(1);
	}
	int status = 0;
	::waitpid(pid, &status, 0);
	return WIFEXITED(status) ? WEXITSTATUS(status) : 3;
}
}  // namespace

TEST(FullDisk, ARawlogThatDoesNotFitFailsAndTheOldOneStays)
{
	const fs::path dir = fs::temp_directory_path() / "omnirange_full_disk";
	fs::remove_all(dir);
	fs::create_directories(dir);
	const std::string path = (dir / "out.rawlog").string();
	// Without a limit it does not fail; that run tells the file's whole size.
	ASSERT_EQ(writeWithLimit(path, RLIM_INFINITY, 12), 1);
	const auto whole = fs::file_size(path);
	const auto isOld = [&] {
		std::ifstream f(path);
		std::string text;
		std::getline(f, text);
		return text == "an older rawlog";
	};
	// Limits that cut the stream in the middle, and in the final flush at close.
	for (const rlim_t limit : {static_cast<rlim_t>(whole / 3), static_cast<rlim_t>(whole - 256)})
	{
		std::ofstream(path) << "an older rawlog";
		EXPECT_EQ(writeWithLimit(path, limit, 12), 0) << "limit " << limit << " of " << whole;
		EXPECT_TRUE(isOld()) << "limit " << limit;
		for (const auto& e : fs::directory_iterator(dir)) EXPECT_EQ(e.path(), fs::path(path)) << "left behind";
	}
}
