#pragma once
// Running real programs from the tests: the project's apps and MRPT's.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace omnirange::e2e
{
const std::string kSource = OMNIRANGE_SOURCE_DIR;
const std::string kApps = OMNIRANGE_APPS_DIR;
const std::string kPlugin = OMNIRANGE_PLUGIN_FILE;

struct RunResult
{
	int code;
	std::string out;  // stdout and stderr
};

/** Runs a shell command with no standard input (MRPT's programs read it). */
inline RunResult run(const std::string& cmd)
{
	RunResult r{-1, ""};
	FILE* p = ::popen(("(" + cmd + ") </dev/null 2>&1").c_str(), "r");
	if (!p) return r;
	char buf[4096];
	while (std::fgets(buf, sizeof buf, p)) r.out += buf;
	const int status = ::pclose(p);
	r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
	return r;
}

inline std::string q(const std::string& s);
/** The same, run in folder `dir`. */
inline RunResult run(const std::string& cmd, const std::string& dir) { return run("cd " + q(dir) + " && " + cmd); }

inline std::string app(const std::string& name) { return "'" + kApps + "/" + name + "'"; }

/** A fresh folder for one test. */
inline std::string workDir(const std::string& name)
{
	const std::string d = testing::TempDir() + "omnirange_e2e/" + name;
	std::filesystem::remove_all(d);
	std::filesystem::create_directories(d);
	return d;
}

inline std::string q(const std::string& s) { return "'" + s + "'"; }

/** The factory sample, trained and scanned into `dir`: returns the scanned rawlog. */
inline std::string scannedFactorySample(const std::string& dir)
{
	const std::string in = kSource + "/rawlogs/factory-sample.rawlog";
	const std::string ini = kSource + "/ini/factory.ini";
	const RunResult t = run(app("omnirange-train") + " -q -i " + q(in) + " -c " + q(ini) + " -o " + q(dir + "/f.hist"));
	EXPECT_EQ(t.code, 0) << t.out;
	const RunResult s = run(app("omnirange-scan") + " -q -i " + q(in) + " -c " + q(ini) + " -H " + q(dir + "/f.hist") +
					  " -o " + q(dir + "/scanned.rawlog"));
	EXPECT_EQ(s.code, 0) << s.out;
	return dir + "/scanned.rawlog";
}

/** "LABEL / COUNT /" rows of rawlog-edit --info. */
inline int labelCount(const std::string& info, const std::string& label)
{
	std::istringstream in(info);
	for (std::string line; std::getline(in, line);)
	{
		const auto at = line.find(" " + label + " /");
		if (line.find("Sensor (Label") != std::string::npos && at != std::string::npos)
			return std::stoi(line.substr(at + label.size() + 3));
	}
	return 0;
}

inline std::vector<std::vector<double>> readTable(const std::string& path)
{
	std::ifstream f(path);
	std::vector<std::vector<double>> rows;
	for (std::string line; std::getline(f, line);)
	{
		std::istringstream in(line);
		std::vector<double> r;
		for (double v; in >> v;) r.push_back(v);
		if (!r.empty()) rows.push_back(r);
	}
	return rows;
}

}  // namespace omnirange::e2e
