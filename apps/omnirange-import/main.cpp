// omnirange-import: see omnirange_apps/ImportApp.h. Parses the command line and runs
// the app; every error ends here as one line on stderr and exit code 1.
#include <omnirange_apps/CommandLine.h>
#include <omnirange_apps/ImportApp.h>

int main(int argc, char** argv)
{
	using omnirange::app::ImportApp;
	return omnirange::app::runApp("omnirange-import", [&] { ImportApp(ImportApp::parse(argc, argv)).run(); });
}
