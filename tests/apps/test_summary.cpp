// The suite's figures: metrics.ini files -> one CSV -> the docs' tables, each
// figure as the run wrote it; an engine worse than the wheels alone is flagged.
#include <omnirange_apps/SummaryApp.h>
#include <omnirange_eval/Summary.h>

#include "../common/FactorySample.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace omnirange;
namespace fs = std::filesystem;

namespace
{
std::string writeReport(const std::string& results, const std::string& name, const std::string& metrics)
{
	fs::create_directories(results + "/" + name);
	std::ofstream(results + "/" + name + "/metrics.ini") << "[metrics]\n" << metrics;
	return results + "/" + name;
}

const std::vector<eval::SuiteEntry> kTwo = {{"maze", "main", "a maze"}, {"lab", "room", "a lab"}};

std::string twoReports(const std::string& name)
{
	const std::string results = test::freshDir("omnirange_summary", name);
	writeReport(results, "maze",
				"accuracy_mean_abs = 0.0165\naccuracy_mean_percent = 1.291\ntruth_within_5cm = 0.983\n"
				"odometry_ate_rmse = 1.169\nicp_OMNISCAN_ate_rmse = 0.179\nicp_OMNISCAN_final_xy = 0.665\n");
	writeReport(results, "lab",
				"accuracy_mean_abs = 0.1993\ntruth_within_5cm = 0.51\nodometry_ate_rmse = 0.3\n"
				"icp_OMNISCAN_ate_rmse = 3.963\nicp_OMNISCAN_final_xy = 5\n");
	return results;
}
}  // namespace

TEST(Summary, MetricsGoThroughTheCsvUnchanged)
{
	const std::string results = twoReports("round_trip");
	const eval::Summary s = eval::collectMetrics(kTwo, results);
	ASSERT_EQ(s.size(), 2u);
	EXPECT_EQ(s[0].name, "maze");
	EXPECT_DOUBLE_EQ(s[0].get("accuracy_mean_abs"), 0.0165);
	EXPECT_TRUE(std::isnan(s[1].get("accuracy_mean_percent")));  // the lab's run did not write it
	const std::string csv = results + "/summary.csv";
	std::ofstream(csv) << eval::toCsv(s);
	const eval::Summary back = eval::readCsv(csv);
	ASSERT_EQ(back.size(), 2u);
	for (std::size_t i = 0; i < 2; ++i)
	{
		EXPECT_EQ(back[i].name, s[i].name);
		EXPECT_EQ(back[i].group, s[i].group);
		EXPECT_EQ(back[i].metrics, s[i].metrics);
	}
}

TEST(Summary, AMissingReportIsAnErrorThatNamesIt)
{
	const std::string results = twoReports("missing");
	fs::remove_all(results + "/lab");
	try
	{
		eval::collectMetrics(kTwo, results);
		ADD_FAILURE() << "no error";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("lab/metrics.ini"), std::string::npos) << e.what();
	}
}

TEST(Summary, AReportIsReadAsStrictlyAsItIsWritten)
{
	const std::vector<std::pair<std::string, std::string>> garbled = {
		{"[metric]\naccuracy_mean_abs = 0.1\n", "[metric] is not a section"},
		{"[metrics]\nAccuracy_Mean_Abs = 0.1\n", "Accuracy_Mean_Abs: not a metric"},
		{"[metrics]\naccuracy_mean_abz = 0.1\n", "accuracy_mean_abz: not a metric"},
		{"[metrics]\naccuracy_mean_abs = -1e308\n", "must be within"},
		{"[metrics]\nicp_OMNI SCAN_ate_rmse = 0.1\n", "not a metric"},
	};
	for (const auto& [text, expected] : garbled)
	{
		const std::string results = test::freshDir("omnirange_summary", "garbled");
		fs::create_directories(results + "/maze");
		std::ofstream(results + "/maze/metrics.ini") << text;
		try
		{
			eval::collectMetrics({{"maze", "main", "a maze"}}, results);
			ADD_FAILURE() << text << ": no error";
		}
		catch (const std::runtime_error& e)
		{
			EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
			EXPECT_NE(std::string(e.what()).find("maze/metrics.ini"), std::string::npos) << e.what();
		}
	}
	// A sensor's keys with the label the ini gave it.
	const std::string results = test::freshDir("omnirange_summary", "labels");
	writeReport(results, "maze", "guarded_FRONT_CAM_loops = 3\ngt_LASER2_check_region_marked = 0.5\n");
	EXPECT_EQ(eval::collectMetrics({{"maze", "main", "a maze"}}, results)[0].get("guarded_FRONT_CAM_loops"), 3.0);
}

TEST(Summary, TablesShowTheRunsFiguresThePapersBesideAndFlagADivergedEngine)
{
	const eval::Summary s = eval::collectMetrics(kTwo, twoReports("tables"));
	const std::string table2 = eval::markdownTable("table2", s);
	EXPECT_NE(table2.find("| maze | 0.138 m | 7.639 % | 0.017 m | 1.291 % |"), std::string::npos) << table2;
	EXPECT_EQ(table2.find("lab"), std::string::npos) << "the paper had no lab";
	const std::string truth = eval::markdownTable("truth", s);
	EXPECT_NE(truth.find("| lab | room | – | 51.0 % |"), std::string::npos) << truth;
	const std::string paths = eval::markdownTable("paths", s);
	// The maze's engine beat the wheels; the lab's is 13 times worse than them.
	EXPECT_NE(paths.find("0.179 m / 0.665 m |"), std::string::npos) << paths;
	EXPECT_NE(paths.find("3.963 m / 5.000 m (worse than odometry)"), std::string::npos) << paths;
	EXPECT_THROW(eval::markdownTable("no-such-table", s), std::runtime_error);
}

TEST(Summary, FillReplacesOnlyTheBlocksAndCheckFindsAStaleOne)
{
	const std::string results = twoReports("fill");
	const std::string csv = results + "/suite.csv";
	std::ofstream(csv) << eval::toCsv(eval::collectMetrics(kTwo, results));
	const std::string page = results + "/page.md";
	const std::string prose = "# Results\n\nText before.\n\n<!-- table: table2 -->\nold figures\n<!-- end table -->\n\nAfter.\n";
	std::ofstream(page) << prose;

	app::SummaryApp::Options o;
	o.csv = csv, o.fill = {page}, o.check = true, o.verbosity = mrpt::system::LVL_ERROR;
	EXPECT_THROW(app::SummaryApp(o).run(), std::runtime_error);  // stale
	EXPECT_EQ(test::readText(page), prose);  // --check changes nothing
	o.check = false;
	app::SummaryApp(o).run();
	const std::string filled = test::readText(page);
	EXPECT_EQ(filled.find("old figures"), std::string::npos);
	EXPECT_EQ(filled.substr(0, filled.find("<!-- table")), "# Results\n\nText before.\n\n");
	EXPECT_EQ(filled.substr(filled.find("<!-- end table -->")), "<!-- end table -->\n\nAfter.\n");
	EXPECT_NE(filled.find("| maze | 0.138 m |"), std::string::npos) << filled;
	o.check = true;
	EXPECT_NO_THROW(app::SummaryApp(o).run());  // now as the CSV gives

	std::ofstream(page) << "<!-- table: table2 -->\nnever closed\n";
	EXPECT_THROW(app::SummaryApp(o).run(), std::runtime_error);

	// A page with CRLF line ends keeps them on every line, its tables' too.
	std::ofstream(page, std::ios::binary) << "# Results\r\n<!-- table: table2 -->\r\nold\r\n<!-- end table -->\r\nAfter.\r\n";
	o.check = false;
	app::SummaryApp(o).run();
	const std::string crlf = test::readText(page);
	std::size_t bare = 0;
	for (std::size_t k = 0; k < crlf.size(); ++k) bare += crlf[k] == '\n' && (k == 0 || crlf[k - 1] != '\r');
	EXPECT_EQ(bare, 0u) << crlf;
	EXPECT_NE(crlf.find("| maze | 0.138 m |"), std::string::npos) << crlf;
}
