#include "omnirange_apps/SummaryApp.h"

#include "omnirange_apps/CommandLine.h"

#include <omnirange_eval/Summary.h>

#include <omnirange/config/Output.h>
#include <omnirange/config/OptionsTable.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

namespace omnirange::app
{
namespace
{
constexpr char kSummaryPageBegins[] = "# omnirange: the experiments' figures";
}  // namespace

SummaryApp::Options SummaryApp::parse(int argc, const char* const* argv)
{
	Options o;
	TCLAP::CmdLine cmd(
		"omnirange-summary: the experiments' metrics in one CSV and one page of tables (PREFIX.csv, PREFIX.md); "
		"or, with --csv, the tables inside Markdown files made again from that CSV (--fill) or checked (--check)",
		' ', "0.1");
	BoundArgs bound(cmd);
	bound.value("s", "suite", "the list of experiments", o.suite, "FILE");
	TCLAP::MultiArg<std::string> group("g", "group", "only this group of the list (repeatable)", false, "GROUP", cmd);
	bound.value("r", "results", "folder of the reports (NAME/metrics.ini)", o.results, "DIR");
	TCLAP::ValueArg<std::string> out("o", "output", "prefix of PREFIX.csv and PREFIX.md", false, "", "PREFIX", cmd);
	TCLAP::ValueArg<std::string> csv("", "csv", "read this CSV instead of the reports", false, "", "FILE", cmd);
	TCLAP::MultiArg<std::string> fill("", "fill", "make this file's table blocks again from --csv (repeatable)", false, "FILE", cmd);
	bound.flag("check", "with --fill: change nothing; exit 1 if a block differs", o.check);
	VerbosityArgs verbosity(cmd);
	parseArgs(cmd, argc, argv);
	bound.fill();
	o.groups = group.getValue();
	o.output = prefixPath(out, "summary"), o.csv = csv.getValue(), o.fill = fill.getValue();
	o.verbosity = verbosity.level();
	if (!o.fill.empty() && o.csv.empty()) throw std::runtime_error("--fill needs --csv");
	if (o.check && o.fill.empty()) throw std::runtime_error("--check needs --fill");
	if (o.fill.empty() && o.output.empty()) throw std::runtime_error("give -o PREFIX, or --csv with --fill");
	if (!o.fill.empty() && !o.output.empty())
		throw std::runtime_error("-o with --fill: --fill makes the named files' tables again in place, and writes nothing else");
	requireDistinctFiles(o);
	return o;
}

void SummaryApp::requireDistinctFiles(const Options& o)
{
	namespace fs = std::filesystem;
	const auto place = [](const std::string& f) { return fs::weakly_canonical(f); };  // through links
	for (const auto& f : o.fill)
		if (!o.csv.empty() && place(f) == place(o.csv))
			throw std::runtime_error("--fill '" + f + "' is the --csv it would be filled from");
	requireNamedOnce(o.fill, "--fill");  // filled twice, the second would read the first's output
}

SummaryApp::SummaryApp(Options o) : mrpt::system::COutputLogger("omnirange-summary"), o_(std::move(o))
{
	setMinLoggingLevel(o_.verbosity);
}

std::string SummaryApp::filledOrChecked(const std::string& file, const std::string& csv, std::string& state)
{
	requireRegularFile(file, "file to fill");
	// A Markdown page of tables, not a disk image: refused before it is read into memory.
	constexpr std::uintmax_t kLargestPage = 64u << 20;
	if (const std::uintmax_t size = std::filesystem::file_size(file); size > kLargestPage)
		throw std::runtime_error("'" + file + "' is " + std::to_string(size >> 20) +
								 " MB: more than a page of tables (64 MB at most)");
	state = fileStateOf(file);  // before it is read: a change after that is not overwritten
	std::ifstream in(file);
	if (!in) throw std::runtime_error("cannot read '" + file + "'");
	std::ostringstream text;
	text << in.rdbuf();
	const eval::Summary table = eval::readCsv(csv);
	// An empty table would fill every block with nothing: the figures would be lost.
	if (table.empty()) throw std::runtime_error(csv + ": no experiment in it (no row under the header)");
	std::string filled;
	try
	{
		filled = eval::fillTables(text.str(), table);
		if (text.str().find("<!-- table: ") == std::string::npos)
			throw std::runtime_error("no table block ('<!-- table: NAME -->' ... '<!-- end table -->') to fill");
	}
	catch (const std::runtime_error& e)
	{
		throw std::runtime_error(file + ": " + e.what());
	}
	if (filled == text.str())
	{
		MRPT_LOG_INFO_STREAM(file << ": its tables are " << csv << "'s");
		return "";
	}
	if (o_.check) throw std::runtime_error(file + ": a table differs from what " + csv + " gives (omnirange-summary --fill)");
	return filled;
}

void SummaryApp::run()
{
	if (!o_.fill.empty())
	{
		// Every page filled, or none: pages that quote one another stay in step.
		OutputSet pages;
		for (const auto& f : o_.fill)
		{
			std::string state;
			if (const std::string filled = filledOrChecked(f, o_.csv, state); !filled.empty())
			{
				pages.write({f, OutputKind::Text}, filled);
				pages.requireUnchanged(f, state);  // a user's edit meanwhile is not lost: the run fails
			}
		}
		pages.commit();
		for (const auto& f : o_.fill) MRPT_LOG_INFO_STREAM(f << ": its tables are " << o_.csv << "'s now");
		return;
	}
	std::vector<eval::SuiteEntry> entries = eval::loadSuite(o_.suite);
	if (!o_.groups.empty())
		entries.erase(std::remove_if(entries.begin(), entries.end(),
									 [&](const auto& e) {
										 return std::find(o_.groups.begin(), o_.groups.end(), e.group) == o_.groups.end();
									 }),
					  entries.end());
	if (entries.empty()) throw std::runtime_error(o_.suite + ": no experiment of the groups asked for");
	const std::vector<Output> outputs{{o_.output + ".csv", OutputKind::Text, eval::kSummaryCsvBegins},
									  {o_.output + ".md", OutputKind::Text, kSummaryPageBegins}};
	requireOutputsAllowed(outputs, "omnirange-summary", {o_.suite, o_.csv});
	const eval::Summary s = o_.csv.empty() ? eval::collectMetrics(entries, o_.results) : eval::readCsv(o_.csv);
	std::string page = std::string(kSummaryPageBegins) + "\n\nMade by omnirange-summary from each report's metrics.ini.\n";
	for (const auto& name : eval::tableNames()) page += "\n## " + name + "\n\n" + eval::markdownTable(name, s);
	OutputSet set("omnirange-summary", {o_.suite, o_.csv});
	set.write(outputs[0], eval::toCsv(s));
	set.write(outputs[1], page);
	set.commit();
	MRPT_LOG_INFO_STREAM("\naccuracy (against the laser and the truth), after the training fifth:\n"
						 << eval::markdownTable("short", s) << "\npath error, ATE RMSE / final position error:\n"
						 << eval::markdownTable("paths", s) << "\nevery table: " << o_.output
						 << ".md; every figure: " << o_.output << ".csv");
}

}  // namespace omnirange::app
