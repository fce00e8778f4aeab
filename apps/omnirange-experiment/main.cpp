// omnirange-experiment: one ini -> simulate, train, scan, accuracy, maps,
// icp-slam, and a report folder (Markdown with figures and tables).
#include "AppMain.h"

#include <omnirange_eval/Experiment.h>

int main(int argc, char** argv)
{
	return omnirange::app::runApp("omnirange-experiment", [&] {
		TCLAP::CmdLine cmd("omnirange-experiment: run a whole experiment described by an ini (ini/maze.ini, ini/factory.ini)", ' ', "0.1");
		TCLAP::UnlabeledValueArg<std::string> ini("ini", "the experiment's ini", true, "", "INI", cmd);
		TCLAP::ValueArg<std::string> output("o", "output", "report folder, overriding the ini's", false, "", "DIR", cmd);
		TCLAP::ValueArg<int> frames("n", "max-frames", "simulate at most this many frames, overriding the ini", false, -1, "N", cmd);
		TCLAP::SwitchArg quiet("q", "quiet", "no progress", cmd);
		omnirange::app::parseArgs(cmd, argc, argv);

		auto config = omnirange::eval::ExperimentConfig::load(ini.getValue());
		if (!output.getValue().empty()) config.output = output.getValue();
		if (frames.getValue() >= 0) config.max_frames = frames.getValue();
		omnirange::eval::Experiment e;
		e.setMinLoggingLevel(quiet.getValue() ? mrpt::system::LVL_ERROR : mrpt::system::LVL_INFO);
		const auto m = e.run(config);
		if (!quiet.getValue())
			std::printf("report: %s/report.md (accuracy: mean absolute difference %.4f m over %.0f pairs)\n",
						config.output.c_str(), m.at("accuracy_mean_abs"), m.at("accuracy_compared"));
		return 0;
	});
}
