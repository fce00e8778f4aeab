#include "omnirange_eval/Summary.h"

#include "omnirange_eval/Experiment.h"

#include "omnirange_eval/Trajectory.h"

#include <omnirange/config/OptionsTable.h>

#include <mrpt/config/CConfigFile.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace omnirange::eval
{
double SummaryRow::get(const std::string& key) const
{
	const auto it = metrics.find(key);
	return it == metrics.end() ? std::numeric_limits<double>::quiet_NaN() : it->second;
}

namespace
{
/** [-] No figure of a run is larger: past it a value is garbled, not measured. */
constexpr double kMaxMetric = 1e9;

/** A report's metrics.ini, as omnirange-experiment writes it: the one
 * section [metrics], only keys a run writes (in their own case), each a
 * finite number. (A key may be missing: a report written before it was.) */
Metrics readMetrics(const std::string& file)
{
	const mrpt::config::CConfigFile ini(file);
	std::vector<std::string> sections, keys;
	ini.getAllSections(sections);
	for (const auto& section : sections)
		if (section != "metrics" && section != "report")
			throw std::runtime_error(file + ": [" + section + "] is not a section of a report's metrics ([metrics], [report])");
	ini.getAllKeys("metrics", keys);
	Metrics m;
	for (const auto& k : keys)
	{
		if (!isMetricKey(k)) throw std::runtime_error(file + ": " + k + ": not a metric omnirange-experiment writes");
		try
		{
			const double v = parseDouble(ini.read_string("metrics", k, "", true));
			if (std::abs(v) > kMaxMetric) throw std::invalid_argument("must be within [-1e9, 1e9]");
			m[k] = v;
		}
		catch (const std::invalid_argument& err)
		{
			throw std::runtime_error(file + ": " + k + ": " + err.what());
		}
	}
	return m;
}
}  // namespace

Summary collectMetrics(const std::vector<SuiteEntry>& entries, const std::string& results_dir)
{
	Summary s;
	for (const auto& e : entries)
	{
		const std::string file = results_dir + "/" + e.name + "/metrics.ini";
		if (!fs::exists(file)) throw std::runtime_error("no report of '" + e.name + "': '" + file + "' is missing");
		requireRegularFile(file, "report");
		requireNoRepeatedKeys(file);  // read as strictly as any ini: a garbled report is not an empty one
		// A report run from another experiment's ini and put here by -o: its figures are not this one's.
		const mrpt::config::CConfigFile ini(file);
		if (const std::string made_by = ini.read_string("report", "experiment", ""); !made_by.empty() && made_by != e.name)
			throw std::runtime_error("'" + file + "' is a report of '" + made_by + "', not of '" + e.name + "'");
		s.push_back({e.name, e.group, readMetrics(file)});
	}
	return s;
}

std::string toCsv(const Summary& s)
{
	std::set<std::string> keys;
	for (const auto& r : s)
		for (const auto& [k, v] : r.metrics) keys.insert(k);
	std::ostringstream o;
	o << kSummaryCsvBegins;
	for (const auto& k : keys) o << "," << k;
	o << "\n";
	for (const auto& r : s)
	{
		o << r.name << "," << r.group;
		for (const auto& k : keys) o << "," << (r.metrics.count(k) ? formatDouble(r.metrics.at(k)) : "");
		o << "\n";
	}
	return o.str();
}

namespace
{
std::vector<std::string> splitCsv(const std::string& line)
{
	std::vector<std::string> cells;
	std::istringstream in(line);
	for (std::string c; std::getline(in, c, ',');) cells.push_back(c);
	if (!line.empty() && line.back() == ',') cells.emplace_back();
	return cells;
}
}  // namespace

Summary readCsv(const std::string& path)
{
	Summary s;
	std::vector<std::string> header;
	forEachDataLine(path, "summary CSV", [&](int, const std::string& line) {
		const auto cells = splitCsv(line);
		if (header.empty())
		{
			if (cells.size() < 2 || cells[0] != "name" || cells[1] != "group")
				throw std::invalid_argument("the first line must be 'name,group,...'");
			header = cells;
			return;
		}
		if (cells.size() != header.size())
			throw std::invalid_argument(std::to_string(cells.size()) + " cells, the header has " +
										std::to_string(header.size()));
		SummaryRow r{cells[0], cells[1], {}};
		for (std::size_t i = 2; i < cells.size(); ++i)
			if (!cells[i].empty()) r.metrics[header[i]] = parseDouble(cells[i]);
		s.push_back(std::move(r));
	});
	return s;
}

namespace
{
std::string fmt(const char* f, double v)
{
	if (std::isnan(v)) return "–";
	char b[64];
	std::snprintf(b, sizeof b, f, v);
	return b;
}
std::string percent(double share) { return fmt("%.1f %%", 100 * share); }
std::string metres(double v) { return fmt("%.3f m", v); }

/** "ATE / final", flagged when the engine lost its way (worseThanOdometry()). */
std::string pathCell(const SummaryRow& r, const std::string& prefix)
{
	const double ate = r.get(prefix + "_ate_rmse"), final_xy = r.get(prefix + "_final_xy");
	return metres(ate) + " / " + metres(final_xy) +
		   (worseThanOdometry(ate, r.get("odometry_ate_rmse")) ? kWorseThanOdometry : "");
}

const std::map<std::string, std::pair<double, double>> kPaperTableII = {
	{"maze", {0.1375, 7.639}}, {"factory", {0.0809, 4.493}}};

void table2(std::ostream& o, const Summary& s)
{
	o << "| world | paper: mean abs. difference | paper: mean % | ours: mean abs. difference | ours: mean % | ours: "
		 "signed mean | pairs excluded |\n|---|---|---|---|---|---|---|\n";
	for (const auto& r : s)
	{
		const auto paper = kPaperTableII.find(r.name);
		if (paper == kPaperTableII.end()) continue;
		o << "| " << r.name << " | " << metres(paper->second.first) << " | " << fmt("%.3f %%", paper->second.second)
		  << " | " << metres(r.get("accuracy_mean_abs")) << " | " << fmt("%.3f %%", r.get("accuracy_mean_percent"))
		  << " | " << metres(r.get("accuracy_signed_mean")) << " | " << percent(r.get("accuracy_excluded_fraction"))
		  << " |\n";
	}
}

void truth(std::ostream& o, const Summary& s)
{
	o << "| world | group | within 2 cm | within 5 cm | within 5 cm, confident rays | false free | unsure | missed | "
		 "false obstacles | mean abs. vs truth | mean abs. vs laser | colour separation (AUC) |\n"
		 "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
	for (const auto& r : s)
		o << "| " << r.name << " | " << r.group << " | " << percent(r.get("truth_within_2cm")) << " | "
		  << percent(r.get("truth_within_5cm")) << " | " << percent(r.get("truth_within_5cm_confident")) << " | "
		  << percent(r.get("truth_false_free")) << " | " << percent(r.get("truth_unsure")) << " | "
		  << percent(r.get("truth_missed")) << " | " << percent(r.get("truth_false_obstacles")) << " | "
		  << metres(r.get("truth_mean_abs")) << " | " << metres(r.get("accuracy_mean_abs")) << " | "
		  << fmt("%.2f", r.get("colour_separation_auc")) << " |\n";
}

void maps(std::ostream& o, const Summary& s)
{
	o << "| world | laser: precision | laser: recall | laser: wall thickness | omnicam: precision | omnicam: recall | "
		 "omnicam: wall thickness |\n|---|---|---|---|---|---|---|\n";
	for (const auto& r : s)
	{
		o << "| " << r.name;
		for (const std::string sensor : {"LASER", "OMNISCAN"})
			o << " | " << fmt("%.3f", r.get("gt_" + sensor + "_precision")) << " | "
			  << fmt("%.3f", r.get("gt_" + sensor + "_recall")) << " | " << metres(r.get("gt_" + sensor + "_thickness"));
		o << " |\n";
	}
}

void paths(std::ostream& o, const Summary& s)
{
	o << "| world | odometry alone | icp-slam, laser | icp-slam, omnicam | guarded, laser | guarded, omnicam |\n"
	  << "|---|---|---|---|---|---|\n";
	for (const auto& r : s)
		o << "| " << r.name << " | " << metres(r.get("odometry_ate_rmse")) << " / " << metres(r.get("odometry_final_xy"))
		  << " | " << pathCell(r, "icp_LASER") << " | " << pathCell(r, "icp_OMNISCAN") << " | "
		  << pathCell(r, "guarded_LASER") << " | " << pathCell(r, "guarded_OMNISCAN") << " |\n";
}

/** The fused scan beside the laser and the omnicam: against what the robot would strike, on the rays the
 * laser sees (Report.cpp's in-view keys), and its maps and paths beside the laser's. */
void fused(std::ostream& o, const Summary& s)
{
	o << "| world | missed: laser | missed: omnicam | missed: fused | false obstacles: laser | false obstacles: fused | "
		 "recall, true poses: laser / fused | precision: laser / fused | guarded path ATE: laser / fused | icp-slam "
		 "path ATE: laser / fused |\n|---|---|---|---|---|---|---|---|---|---|\n";
	for (const auto& r : s)
	{
		const auto pair = [&](const std::string& prefix, const std::string& what, const auto& show) {
			return show(r.get(prefix + "_LASER_" + what)) + " / " + show(r.get(prefix + "_FUSED_" + what));
		};
		const auto ratio = [](double x) { return fmt("%.3f", x); };
		o << "| " << r.name << " | " << percent(r.get("body_LASER_missed")) << " | "
		  << percent(r.get("body_OMNISCAN_missed")) << " | " << percent(r.get("body_FUSED_missed")) << " | "
		  << percent(r.get("body_LASER_false_obstacles")) << " | " << percent(r.get("body_FUSED_false_obstacles"))
		  << " | " << pair("gt", "recall", ratio) << " | " << pair("gt", "precision", ratio) << " | "
		  << pair("guarded", "ate_rmse", metres) << " | " << pair("icp", "ate_rmse", metres) << " |\n";
	}
}

void clocks(std::ostream& o, const Summary& s)
{
	o << "| world | frames | run |\n|---|---|---|\n";
	double total = 0;
	for (const auto& r : s)
	{
		o << "| " << r.name << " | " << fmt("%.0f", r.get("frames")) << " | " << fmt("%.0f s", r.get("seconds")) << " |\n";
		total += r.get("seconds");
	}
	o << "| all, one after another | | " << fmt("%.0f s", total) << " |\n";
}

double median(std::vector<double> v)
{
	v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return std::isnan(x); }), v.end());  // not measured
	if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
	std::sort(v.begin(), v.end());
	return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

void shortTable(std::ostream& o, const Summary& s)
{
	o << "| world | mean abs. vs laser (paper) | within 5 cm of the truth | false free | unsure | guarded path ATE, "
		 "omnicam |\n"
	  << "|---|---|---|---|---|---|\n";
	std::map<std::string, std::vector<const SummaryRow*>> groups;
	for (const auto& r : s)
	{
		const auto paper = kPaperTableII.find(r.name);
		if (r.group != "room")
		{
			o << "| " << r.name << " | " << metres(r.get("accuracy_mean_abs"))
			  << (paper != kPaperTableII.end() ? " (" + metres(paper->second.first) + ")" : "") << " | "
			  << percent(r.get("truth_within_5cm")) << " | " << percent(r.get("truth_false_free")) << " | "
			  << percent(r.get("truth_unsure")) << " | " << metres(r.get("guarded_OMNISCAN_ate_rmse")) << " |\n";
			continue;
		}
		groups[r.group].push_back(&r);
	}
	for (const auto& [group, rows] : groups)
	{
		const auto med = [&](const std::string& key) {
			std::vector<double> v;
			for (const auto* r : rows) v.push_back(r->get(key));
			return median(v);
		};
		o << "| held-out rooms, median | " << metres(med("accuracy_mean_abs")) << " | "
		  << percent(med("truth_within_5cm")) << " | " << percent(med("truth_false_free")) << " | "
		  << percent(med("truth_unsure")) << " | " << metres(med("guarded_OMNISCAN_ate_rmse")) << " |\n";
	}
}

using TableWriter = void (*)(std::ostream&, const Summary&);
const std::vector<std::pair<std::string, TableWriter>>& writers()
{
	static const std::vector<std::pair<std::string, TableWriter>> w = {
		{"table2", table2}, {"truth", truth}, {"maps", maps}, {"paths", paths}, {"fused", fused}, {"time", clocks}, {"short", shortTable}};
	return w;
}
}  // namespace

const std::vector<std::string>& tableNames()
{
	static const std::vector<std::string> names = [] {
		std::vector<std::string> n;
		for (const auto& [name, w] : writers()) n.push_back(name);
		return n;
	}();
	return names;
}

std::string markdownTable(const std::string& name, const Summary& s)
{
	for (const auto& [n, write] : writers())
		if (n == name)
		{
			std::ostringstream o;
			write(o, s);
			return o.str();
		}
	throw std::runtime_error("no table '" + name + "'");
}

namespace
{
/** The first cell of each row of a Markdown table (its experiment), the header and rule left out. */
std::vector<std::string> rowNames(const std::string& table)
{
	std::vector<std::string> names;
	std::istringstream in(table);
	int row = 0;
	for (std::string line; std::getline(in, line);)
		if (!line.empty() && line[0] == '|' && ++row > 2)
			names.push_back(trimmed(line.substr(1, line.find('|', 1) - 1)));
	return names;
}

/** A block filled from a CSV that lacks some of its experiments would lose
 * their rows without a word: an error naming them (fill from the whole suite's CSV). */
void requireNoRowLost(const std::string& block, const std::string& before, const std::string& after)
{
	const auto now = rowNames(after);
	std::string lost;
	for (const auto& name : rowNames(before))
		if (std::find(now.begin(), now.end(), name) == now.end()) lost += (lost.empty() ? "" : ", ") + name;
	if (!lost.empty())
		throw std::runtime_error("table '" + block + "' would lose its rows for " + lost +
								 ": the CSV has no figures for them (fill from a CSV of every experiment the table shows)");
}
}  // namespace

std::string fillTables(const std::string& text, const Summary& s)
{
	static const std::string open = "<!-- table: ", close = "<!-- end table -->";
	const std::size_t first_end = text.find('\n');
	const bool crlf = first_end != std::string::npos && first_end > 0 && text[first_end - 1] == '\r';
	std::string out;
	std::size_t at = 0;
	for (std::size_t start; (start = text.find(open, at)) != std::string::npos;)
	{
		const std::size_t name_end = text.find(" -->", start);
		const std::size_t end = text.find(close, start);
		const std::size_t next = text.find(open, start + open.size());
		// A block that reaches the next block's opener would swallow it and the text between.
		if (name_end == std::string::npos || end == std::string::npos || (next != std::string::npos && next < end))
			throw std::runtime_error("a table block opened at line " +
									 std::to_string(1 + std::count(text.begin(), text.begin() + static_cast<long>(start), '\n')) +
									 " is not closed before the next one opens");
		const std::string name = text.substr(start + open.size(), name_end - start - open.size());
		std::string table = markdownTable(name, s);
		requireNoRowLost(name, text.substr(name_end + 4, end - name_end - 4), table);
		if (crlf)  // a file written with CRLF line ends keeps them in its tables too
			for (std::size_t k = 0; (k = table.find('\n', k)) != std::string::npos; k += 2) table.insert(k, "\r");
		out += text.substr(at, name_end + 4 - at) + (crlf ? "\r\n" : "\n") + table + close;
		at = end + close.size();
	}
	return out + text.substr(at);
}

}  // namespace omnirange::eval
