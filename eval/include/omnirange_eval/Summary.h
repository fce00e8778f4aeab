#pragma once
// The suite's figures in one place: each experiment's metrics.ini becomes a
// row of one CSV, and every table of docs/results.md and README.md is made
// from those rows, so a figure in the docs is the figure a run wrote.

#include "omnirange_eval/Suite.h"

#include <map>
#include <string>
#include <vector>

namespace omnirange::eval
{
struct SummaryRow
{
	std::string name, group;
	std::map<std::string, double> metrics;  ///< metrics.ini's keys

	/** The metric `key`; NaN when the run did not write it. */
	double get(const std::string& key) const;
};
using Summary = std::vector<SummaryRow>;

/** RESULTS/NAME/metrics.ini of each entry, in the suite's order. Throws
 * std::runtime_error naming a report that is missing or unreadable. */
Summary collectMetrics(const std::vector<SuiteEntry>& entries, const std::string& results_dir);

/** How toCsv() begins (config/Output.h's begins_with). */
inline constexpr char kSummaryCsvBegins[] = "name,group";
/** One row per experiment: name, group, then every metric (sorted by key). */
std::string toCsv(const Summary& s);
/** What toCsv() wrote. Throws std::runtime_error("PATH:LINE: why"). */
Summary readCsv(const std::string& path);

/** The tables, by name: "table2" (the paper's Table II beside ours),
 * "truth" (against the true floor boundary), "maps" (ground-truth poses),
 * "paths" (each engine), "time" (each run's clock), "short" (the README's). */
const std::vector<std::string>& tableNames();
/** The table `name` in Markdown, for the rows of `s` it covers. */
std::string markdownTable(const std::string& name, const Summary& s);

/** `text` with every block between "<!-- table: NAME -->" and
 * "<!-- end table -->" replaced by markdownTable(NAME). Throws
 * std::runtime_error on an unknown name or an unclosed block. */
std::string fillTables(const std::string& text, const Summary& s);

}  // namespace omnirange::eval
