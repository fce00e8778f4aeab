// omnirange-slam: see omnirange_apps/SlamApp.h. Parses the command line and runs
// the app; every error ends here as one line on stderr and exit code 1.
#include <omnirange_apps/CommandLine.h>
#include <omnirange_apps/SlamApp.h>

int main(int argc, char** argv)
{
	using omnirange::app::SlamApp;
	return omnirange::app::runApp("omnirange-slam", [&] { SlamApp(SlamApp::parse(argc, argv)).run(); });
}
