#include "omnirange_apps/ExperimentApp.h"

#include "omnirange_apps/CommandLine.h"

#include <filesystem>

namespace omnirange::app
{
ExperimentApp::Options ExperimentApp::parse(int argc, const char* const* argv)
{
	Options o;
	TCLAP::CmdLine cmd("omnirange-experiment: run a whole experiment described by an ini (ini/maze.ini, ini/factory.ini)", ' ', "0.1");
	TCLAP::UnlabeledValueArg<std::string> ini("ini", "the experiment's ini", true, "", "INI", cmd);
	TCLAP::ValueArg<std::string> output("o", "output", "report folder, overriding the ini's", false, "", "DIR", cmd);
	TCLAP::ValueArg<int> frames("n", "max-frames", "simulate at most this many frames, overriding the ini", false, o.max_frames, "N", cmd);
	BoundArgs bound(cmd);
	bound.value("", "robot", "robot ini for the simulator, overriding the ini's", o.robot, "INI");
	bound.flag("study-candidates",
			   "with learn = true, also score every candidate learning tried on the rest of the route against the truth, "
			   "into candidates_on_route.csv in the report folder (a study; minutes more)",
			   o.study_candidates);
	ForceArg force(cmd);
	VerbosityArgs verbosity(cmd);
	parseArgs(cmd, argc, argv);
	bound.fill();
	o.ini = ini.getValue(), o.output = output.getValue(), o.max_frames = frames.getValue();
	if (frames.isSet() && o.max_frames < 1) throw std::invalid_argument("-n must be at least 1 frame");
	if (output.isSet()) o.output = requiredPath(output);
	o.force = force.value();
	o.verbosity = verbosity.level();
	return o;
}

eval::Metrics ExperimentApp::run()
{
	auto config = eval::ExperimentConfig::load(o_.ini);
	if (!o_.output.empty()) config.output = o_.output;
	if (o_.max_frames >= 0) config.max_frames = o_.max_frames;
	if (!o_.robot.empty())
	{
		if (!std::filesystem::is_regular_file(o_.robot)) throw std::runtime_error("cannot open robot ini '" + o_.robot + "'");
		config.robot = o_.robot;
	}
	if (o_.study_candidates && !config.learn)
		throw std::runtime_error("--study-candidates needs learn = true in '" + o_.ini + "': it studies learning's candidates");
	eval::Experiment e(config);
	e.setForce(o_.force);
	e.setMinLoggingLevel(o_.verbosity);
	e.setCandidateStudy(o_.study_candidates);
	const auto m = e.run();
	if (const auto mean = m.find("accuracy_mean_abs"); mean != m.end())
		e.logFmt(mrpt::system::LVL_INFO, "report: %s/report.md (accuracy: mean absolute difference %.4f m over %.0f pairs)",
				 config.output.c_str(), mean->second, m.at("accuracy_compared"));
	else  // every ray the laser sees is unsure
		e.logFmt(mrpt::system::LVL_INFO, "report: %s/report.md (accuracy: no ray compared, every one unsure)",
				 config.output.c_str());
	return m;
}

}  // namespace omnirange::app
