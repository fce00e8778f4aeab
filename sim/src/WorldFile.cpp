// The world file reader. Syntax: docs/worlds.md. Every error names the file
// and the line.
#include <omnirange/config/OptionsTable.h>
#include "WorldFields.h"

#include "omnirange_sim/World.h"

#include <omnirange/io/GzObject.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace omnirange::sim
{
namespace
{
/** A character as a message shows it: 'x', or a control character by its code. */
std::string shown(char c)
{
	if (c == '\t') return "'\\t'";
	if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) >= 127)
		return "byte " + std::to_string(static_cast<unsigned char>(c));
	return std::string("'") + c + "'";
}

struct LegendEntry
{
	int material;
	double z0, z1, gap0, gap1;
};

class Parser
{
   public:
	explicit Parser(const std::string& path) : path_(path) { w_.file = path; }

	World run()
	{
		requireRegularFile(path_, "world file");
		std::ifstream f(path_);
		if (!f) throw std::runtime_error(path_ + ": cannot open world file");
		w_.materials = stockMaterials();
		w_.floor_material = w_.findMaterial("concrete");
		bool header = false;
		for (std::string raw; readCappedLine(f, raw, path_, line_ + 1, "world file");)
		{
			++line_;
			const auto tokens = split(raw);
			if (tokens.empty()) continue;
			if (!header)
			{
				if (tokens[0] != "omnirange-world" || tokens.size() != 2 || tokens[1] != "1")
					throw error("the first line must be 'omnirange-world 1'");
				header = true;
			}
			else if (tokens[0] == "plan")
				plan(fields(tokens), f);  // reads the lines of the plan that follow
			else if (tokens[0] == "name")
			{
				if (tokens.size() != 2) throw error("expected 'name NAME'");
				if (!w_.name.empty()) throw error("a second 'name' line (the first said '" + w_.name + "')");
				w_.name = tokens[1];
			}
			else
				statement(tokens[0], fields(tokens));
		}
		if (!header) throw error("empty world file");
		if (w_.name.empty()) w_.name = "world";
		w_.buildIndex();
		return std::move(w_);
	}

	/** A statement that sets one thing of the world (its bounds, a
	 * material by name) given again: the later would silently win. */
	void requireOnce(const std::string& what)
	{
		const auto [it, fresh] = seen_.emplace(what, line_);
		if (!fresh) throw error(what + " is given a second time (first at line " + std::to_string(it->second) + ")");
	}

	/** One statement line other than the header, name and plan. */
	void statement(const std::string& cmd, const Fields& fl)
	{
		if (cmd == "bounds" || cmd == "floor" || cmd == "sky" || cmd == "light") requireOnce("'" + cmd + "'");
		if (cmd == "bounds")
		{
			w_.lo = {fl.num("xmin"), fl.num("ymin")};
			w_.hi = {fl.num("xmax"), fl.num("ymax")};
			if (!(w_.hi.x > w_.lo.x && w_.hi.y > w_.lo.y))
				throw error("bounds need xmax > xmin and ymax > ymin");
			if (!(std::max({std::abs(w_.lo.x), std::abs(w_.lo.y), std::abs(w_.hi.x), std::abs(w_.hi.y)}) <=
				  kMaxWorldCoordinate))
				throw error("bounds beyond " + std::to_string(static_cast<int>(kMaxWorldCoordinate)) + " m from the origin");
			have_bounds_ = true;
		}
		else if (cmd == "floor")
			w_.floor_material = material(fl);
		else if (cmd == "sky")
		{
			const auto c = fl.rgb("rgb");
			for (int i = 0; i < 3; ++i) w_.sky_rgb[i] = static_cast<std::uint8_t>(c[i]);
		}
		else if (cmd == "light")
		{
			w_.light.azimuth = fl.num("azimuth", w_.light.azimuth);
			w_.light.elevation = fl.num("elevation", w_.light.elevation);
			w_.light.ambient = fl.num("ambient", w_.light.ambient);
			w_.light.diffuse = fl.num("diffuse", w_.light.diffuse);
			w_.light.occlusion = fl.num("occlusion", w_.light.occlusion);
			w_.light.occlusion_radius = fl.num("occlusion_radius", w_.light.occlusion_radius);
			if (!(w_.light.occlusion >= 0 && w_.light.occlusion <= 1 && w_.light.occlusion_radius > 0))
				throw error("light occlusion must be in [0, 1] and occlusion_radius > 0 m");
			if (!(w_.light.elevation > 0.05 && w_.light.elevation <= 1.5708))
				throw error("light elevation must be in (0.05, pi/2] rad");
		}
		else if (cmd == "material")
			defineMaterial(fl);
		else if (cmd == "legend")
			legend(fl);
		else if (cmd == "box")
			add(fl, Footprint::box({fl.num("x"), fl.num("y")}, fl.positive("w"),
								   fl.positive("d"), fl.num("yaw", 0.0)));
		else if (cmd == "wall")
			wall(fl);
		else if (cmd == "cylinder")
			add(fl, Footprint::circle({fl.num("x"), fl.num("y")}, fl.positive("r")));
		else if (cmd == "arc")
			arc(fl);
		else if (cmd == "polygon")
			add(fl, polygon(fl));
		else if (cmd == "gridmap")
			gridmap(fl, have_bounds_);
		else
			throw error("unknown statement '" + cmd + "'");
		fl.requireAllUsed();
	}

   private:
	std::string path_;
	int line_{0};
	std::map<std::string, int> seen_;  // what requireOnce() has seen -> its line
	World w_;
	std::map<char, LegendEntry> legend_;
	bool have_bounds_{false};

	std::string where() const { return path_ + ":" + std::to_string(line_); }
	std::runtime_error error(const std::string& what) const
	{
		return std::runtime_error(where() + ": " + what);
	}

	/** Tokens of a line; a comment starts at a '#' that begins a word. */
	static std::vector<std::string> split(const std::string& raw)
	{
		std::size_t hash = 0;
		while ((hash = raw.find('#', hash)) != std::string::npos &&
			   hash > 0 && !std::isspace(static_cast<unsigned char>(raw[hash - 1])))
			++hash;
		const std::string s = raw.substr(0, hash);
		std::istringstream in(s);
		std::vector<std::string> out;
		for (std::string t; in >> t;) out.push_back(t);
		return out;
	}

	Fields fields(const std::vector<std::string>& tokens) const
	{
		return Fields(where(), {tokens.begin() + 1, tokens.end()});
	}

	int material(const Fields& fl) const
	{
		const std::string name = fl.str("material");
		const int m = w_.findMaterial(name);
		if (m < 0) throw error("unknown material '" + name + "'");
		return m;
	}

	void defineMaterial(const Fields& fl)
	{
		Material m;
		m.name = fl.str("name");
		requireOnce("material '" + m.name + "'");  // a stock one may be redefined, once
		m.rgb = fl.rgb("rgb");
		m.grain = fl.has("grain") ? fl.positive("grain") : m.grain;
		m.grain_contrast = fl.num("grain_contrast", m.grain_contrast);
		m.patch = fl.has("patch") ? fl.positive("patch") : m.patch;
		m.patch_contrast = fl.num("patch_contrast", m.patch_contrast);
		m.hue_jitter = fl.num("hue_jitter", m.hue_jitter);
		m.pattern = fl.has("pattern") ? fl.str("pattern") : m.pattern;
		if (m.pattern != "none" && m.pattern != "tiles" && m.pattern != "planks")
			throw error("pattern must be none, tiles or planks");
		m.pattern_size = fl.has("pattern_size") ? fl.positive("pattern_size") : m.pattern_size;
		m.pattern_width = fl.num("pattern_width", m.pattern_width);
		if (fl.has("pattern_rgb")) m.pattern_rgb = fl.rgb("pattern_rgb");
		const int existing = w_.findMaterial(m.name);
		if (existing >= 0)
			w_.materials[existing] = m;
		else
			w_.materials.push_back(m);
	}

	void add(const Fields& fl, const Footprint& fp)
	{
		const double z0 = fl.num("z0", 0.0), z1 = fl.num("z1");
		if (z0 < 0 || !(z1 > z0)) throw error("need 0 <= z0 < z1");
		addSolid(fp, z0, z1, material(fl));
	}

	/** Every solid (a statement's, a plan's cells, a grid map's) comes in
	 * here: the one place that keeps the world within its size limit. */
	void addSolid(const Footprint& fp, double z0, double z1, int material)
	{
		for (const Vec2& c : {fp.lo(), fp.hi()})
			if (!(std::abs(c.x) <= kMaxWorldCoordinate && std::abs(c.y) <= kMaxWorldCoordinate))
				throw error("the solid reaches beyond " + std::to_string(static_cast<int>(kMaxWorldCoordinate)) +
							" m from the origin");
		if (w_.solids.size() >= kMaxWorldSolids)
			throw error("more than " + std::to_string(kMaxWorldSolids) + " solids: a world this large would take minutes a frame");
		w_.solids.push_back({fp, z0, z1, material, line_});
	}

	void wall(const Fields& fl)
	{
		const Vec2 a{fl.num("x0"), fl.num("y0")}, b{fl.num("x1"), fl.num("y1")};
		const double len = (b - a).norm();
		if (!(len > 0)) throw error("a wall needs two different end points");
		const double t = fl.positive("thickness");
		// The wall's box covers the segment plus half the thickness at each end,
		// so walls that meet at a corner close it.
		add(fl, Footprint::box((a + b) * 0.5, len + t, t, std::atan2(b.y - a.y, b.x - a.x)));
	}

	void arc(const Fields& fl)
	{
		const Vec2 c{fl.num("x"), fl.num("y")};
		const double r = fl.positive("r"), a0 = fl.num("a0"), a1 = fl.num("a1");
		const double t = fl.positive("thickness");
		const int n = static_cast<int>(fl.num("segments", 16));
		if (n < 1 || n > 1000) throw error("segments must be in 1..1000");
		if (!(t < r)) throw error("an arc's thickness must be below its radius");
		for (int i = 0; i < n; ++i)
		{
			const double b0 = a0 + (a1 - a0) * i / n, b1 = a0 + (a1 - a0) * (i + 1) / n;
			const auto at = [&](double rad, double ang) {
				return c + Vec2{std::cos(ang), std::sin(ang)} * rad;
			};
			add(fl, Footprint::polygon({at(r - t / 2, b0), at(r + t / 2, b0), at(r + t / 2, b1),
										at(r - t / 2, b1)}));
		}
	}

	Footprint polygon(const Fields& fl) const
	{
		std::vector<Vec2> pts;
		std::istringstream s(fl.str("points"));
		for (std::string p; std::getline(s, p, ';');)
		{
			double x, y;
			char comma;
			std::istringstream ps(p);
			if (!(ps >> x >> comma >> y)) throw error("points must be x,y;x,y;...");
			pts.push_back({x, y});
		}
		try
		{
			return Footprint::polygon(pts);
		}
		catch (const std::invalid_argument& e)
		{
			throw error(e.what());
		}
	}

	void legend(const Fields& fl)
	{
		const std::string c = fl.str("char");
		if (c.size() != 1 || c == "." || c == " ") throw error("legend char must be one character other than '.'");
		LegendEntry e{material(fl), fl.num("z0", 0.0), fl.num("z1"), fl.num("gap0", -1),
					  fl.num("gap1", -1)};
		if (e.z0 < 0 || !(e.z1 > e.z0)) throw error("need 0 <= z0 < z1");
		if (fl.has("gap0") && !(e.gap0 > e.z0 && e.gap1 > e.gap0 && e.gap1 < e.z1))
			throw error("a gap needs z0 < gap0 < gap1 < z1");
		legend_[c[0]] = e;
	}

	void plan(const Fields& fl, std::istream& in)
	{
		const double x0 = fl.num("x0"), y0 = fl.num("y0"), cell = fl.positive("cell");
		fl.requireAllUsed();
		std::string row;
		int r = 0;
		while (readCappedLine(in, row, path_, line_ + 1, "world file"))
		{
			++line_;
			if (!row.empty() && row.back() == '\r') row.pop_back();  // a file saved with CRLF line ends
			if (row == "end") return;
			// Merge runs of one character into one box per row.
			for (std::size_t c = 0; c < row.size();)
			{
				const char ch = row[c];
				std::size_t e = c;
				while (e < row.size() && row[e] == ch) ++e;
				if (ch != '.' && ch != ' ')
				{
					const auto it = legend_.find(ch);
					if (it == legend_.end())
						throw error("plan character " + shown(ch) + " has no legend");
					const LegendEntry& L = it->second;
					const Footprint fp = Footprint::box(
						{x0 + cell * 0.5 * (c + e), y0 - cell * (r + 0.5)}, cell * (e - c), cell, 0.0);
					if (L.gap0 > 0)
					{
						addSolid(fp, L.z0, L.gap0, L.material);
						addSolid(fp, L.gap1, L.z1, L.material);
					}
					else
						addSolid(fp, L.z0, L.z1, L.material);
				}
				c = e;
			}
			++r;
		}
		throw error("plan without 'end'");
	}

	void gridmap(const Fields& fl, bool have_bounds)
	{
		std::string file = fl.str("file");
		if (file.rfind("mrpt:", 0) == 0)
			file = std::string(MRPT_DATASETS_DIR) + "/" + file.substr(5);
		else if (!file.empty() && file[0] != '/')
		{
			const auto slash = path_.rfind('/');
			if (slash != std::string::npos) file = path_.substr(0, slash + 1) + file;
		}
		w_.maps.push_back(file);
		mrpt::maps::COccupancyGridMap2D grid;
		try
		{
			grid = readGzObject<mrpt::maps::COccupancyGridMap2D>(file, "grid map");
		}
		catch (const std::exception& e)
		{
			throw error("cannot read grid map '" + file + "': " +
						std::string(e.what()).substr(0, 200));
		}
		const double z0 = fl.num("z0", 0.0), z1 = fl.num("z1");
		const double below = fl.num("occupied_below", 0.4);
		if (z0 < 0 || !(z1 > z0)) throw error("need 0 <= z0 < z1");
		const int m = material(fl);
		const double res = grid.getResolution();
		for (unsigned y = 0; y < grid.getSizeY(); ++y)
			for (unsigned x = 0; x < grid.getSizeX();)
			{
				// getCell() is the probability of the cell being free.
				const auto occ = [&](unsigned i) { return grid.getCell(i, y) < below; };
				if (!occ(x))
				{
					++x;
					continue;
				}
				unsigned e = x;
				while (e < grid.getSizeX() && occ(e)) ++e;
				const double cx = grid.getXMin() + res * 0.5 * (x + e);
				const double cy = grid.getYMin() + res * (y + 0.5);
				addSolid(Footprint::box({cx, cy}, res * (e - x), res, 0.0), z0, z1, m);
				x = e;
			}
		if (!have_bounds)
		{
			w_.lo = {grid.getXMin(), grid.getYMin()};
			w_.hi = {grid.getXMax(), grid.getYMax()};
		}
	}
};
}  // namespace

World loadWorld(const std::string& path) { return Parser(path).run(); }

}  // namespace omnirange::sim
