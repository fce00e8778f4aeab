// omnirange-summary: see omnirange_apps/SummaryApp.h. Parses the command line and runs
// the app; every error ends here as one line on stderr and exit code 1.
#include <omnirange_apps/CommandLine.h>
#include <omnirange_apps/SummaryApp.h>

int main(int argc, char** argv)
{
	using omnirange::app::SummaryApp;
	return omnirange::app::runApp("omnirange-summary", [&] { SummaryApp(SummaryApp::parse(argc, argv)).run(); });
}
