// omnirange-train: see omnirange_apps/TrainApp.h. Parses the command line and runs
// the app; every error ends here as one line on stderr and exit code 1.
#include <omnirange_apps/TrainApp.h>
#include <omnirange_apps/CommandLine.h>

int main(int argc, char** argv)
{
	using omnirange::app::TrainApp;
	return omnirange::app::runApp("omnirange-train", [&] { TrainApp(TrainApp::parse(argc, argv)).run(); });
}
