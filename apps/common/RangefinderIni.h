#pragma once
// Loading the rangefinder's ini section in an app, with the file named in errors.

#include <omnirange/Rangefinder.h>

#include <mrpt/config/CConfigFile.h>

#include <filesystem>
#include <stdexcept>

namespace omnirange::app
{
inline RangefinderParams loadRangefinderIni(const std::string& file, const std::string& section)
{
	if (!std::filesystem::is_regular_file(file)) throw std::runtime_error("cannot open ini file '" + file + "'");
	RangefinderParams p;
	try
	{
		p.loadFromConfig(mrpt::config::CConfigFile(file), section);
	}
	catch (const std::invalid_argument& e)
	{
		throw std::runtime_error(file + ": " + e.what());
	}
	return p;
}
}  // namespace omnirange::app
