// omnirange-experiment: see omnirange_apps/ExperimentApp.h. Parses the command line and runs
// the app; every error ends here as one line on stderr and exit code 1.
#include <omnirange_apps/ExperimentApp.h>
#include <omnirange_apps/CommandLine.h>

int main(int argc, char** argv)
{
	using omnirange::app::ExperimentApp;
	return omnirange::app::runApp("omnirange-experiment", [&] { ExperimentApp(ExperimentApp::parse(argc, argv)).run(); });
}
