// The [rangefinder] section of an ini file, as omnirange-scan, -train and the
// sensor read it; a section that loads must also build a rangefinder (its
// tables are sized by the ini's values: the resource limits).
#include "FuzzInput.h"

#include <omnirange/core/Rangefinder.h>
#include <omnirange/config/OptionsTable.h>

#include <mrpt/config/CConfigFile.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
	const omnirange::fuzz::FuzzInput in(data, size, "f.ini");
	omnirange::fuzz::expectEitherResultOrError([&] {
		omnirange::requireNoRepeatedKeys(in.path());
		omnirange::RangefinderParams p;
		p.loadFromConfig(mrpt::config::CConfigFile(in.path()), "rangefinder");
		const omnirange::Rangefinder rf(p, omnirange::ColourModel());
		(void)rf.params().asIni();
	});
	return 0;
}
