#include "omnirange/config/LayeredIni.h"

#include <omnirange/config/Output.h>
#include "omnirange/config/OptionsTable.h"

#include <mrpt/config/CConfigFile.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace omnirange
{
namespace
{
constexpr std::size_t kMaxIniLayers = 16;  // inis deep in 'base =' lines
}  // namespace

std::filesystem::path iniFolderOf(const std::string& ini)
{
	std::error_code ec;
	const fs::path real = fs::weakly_canonical(fs::absolute(ini), ec);
	return (ec ? fs::absolute(ini) : real).parent_path();
}

std::string iniBaseOf(const std::string& path)
{
	requireRegularFile(path, "ini file");
	std::ifstream f(path);
	if (!f) throw std::runtime_error("cannot open ini file '" + path + "'");
	for (std::string line; std::getline(f, line);)
	{
		const IniLine l = parseIniLine(line);
		if (l.kind == IniLine::Kind::Section) break;  // the base comes before any section
		if (l.kind != IniLine::Kind::Key || l.name != "base") continue;
		const std::string value = trimmed(line.substr(line.find('=') + 1));
		if (value.empty()) throw std::runtime_error(path + ": 'base =' names no file");
		const fs::path p(value);
		return p.is_absolute() ? value : (iniFolderOf(path) / p).lexically_normal().string();
	}
	return {};
}

std::vector<std::string> iniBasesOf(const std::string& path)
{
	std::vector<std::string> bases;
	try
	{
		for (std::string base = path; bases.size() < kMaxIniLayers && !(base = iniBaseOf(base)).empty();) bases.push_back(base);
	}
	catch (const std::exception&)
	{
	}
	return bases;
}

LayeredIni readLayeredIni(const std::string& path)
{
	LayeredIni ini;
	for (std::string file = path; !file.empty(); file = iniBaseOf(file))
	{
		requireRegularFile(file, ini.files.empty() ? "ini file" : "base ini");
		if (!fs::is_regular_file(file))
			throw std::runtime_error(ini.files.empty() ? "cannot open ini file '" + file + "'"
													   : ini.files.back() + ": its base '" + file + "' is not a file");
		const std::string canonical = fs::canonical(file).string();
		for (const auto& seen : ini.files)
			if (fs::canonical(seen).string() == canonical)
				throw std::runtime_error(file + ": its bases lead back to it");
		requireNoRepeatedKeys(file);
		ini.files.push_back(file);
		// Ours go two or three deep; thousands would take minutes to read.
		if (ini.files.size() > kMaxIniLayers)
			throw std::runtime_error(path + ": more than " + std::to_string(kMaxIniLayers) + " inis deep in 'base =' lines");
	}
	std::reverse(ini.files.begin(), ini.files.end());
	// Sections in first-seen order, keys in each, later files replacing values.
	std::vector<std::pair<std::string, std::vector<std::pair<std::string, std::string>>>> sections;
	for (const auto& file : ini.files)
	{
		const mrpt::config::CConfigFile layer(file);
		std::vector<std::string> names;
		layer.getAllSections(names);
		for (const auto& s : names)
		{
			if (s.empty()) continue;  // the `base` line, outside every section
			auto at = std::find_if(sections.begin(), sections.end(), [&](const auto& e) { return e.first == s; });
			if (at == sections.end()) at = sections.insert(sections.end(), {s, {}});
			std::vector<std::string> keys;
			layer.getAllKeys(s, keys);
			for (const auto& k : keys)
			{
				const std::string v = layer.read_string(s, k, "", true);
				auto kv = std::find_if(at->second.begin(), at->second.end(), [&](const auto& e) { return e.first == k; });
				if (kv == at->second.end()) at->second.emplace_back(k, v);
				else kv->second = v;
				ini.origin[s + "/" + k] = file;
			}
		}
	}
	std::string text;
	for (const auto& [s, keys] : sections)
	{
		text += "[" + s + "]\n";
		for (const auto& [k, v] : keys) text += k + " = " + v + "\n";
	}
	ini.merged = std::make_shared<mrpt::config::CConfigFileMemory>(text);
	return ini;
}

std::string namingItsFile(const LayeredIni& ini, const std::string& path, const std::exception& e)
{
	std::string file = path;
	const std::string what = e.what();
	std::string section, key;
	if (const auto* k = dynamic_cast<const KeyError*>(&e)) section = k->section, key = k->key;
	// A check of values after loading (validate()) says "[section] key ...", its first key the one it is about.
	else if (const auto close = what.find("] "); what.rfind("[", 0) == 0 && close != std::string::npos)
	{
		section = what.substr(1, close - 1);
		const auto from = close + 2;
		key = what.substr(from, what.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_", from) - from);
	}
	if (const std::string from = ini.originOf(section, key); !from.empty()) file = from;
	return file + ": " + what;
}

}  // namespace omnirange
