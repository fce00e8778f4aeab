#pragma once
// The simulated world: a floor, vertical prisms (solids) of given materials,
// a sun. Read from a world file (docs/worlds.md) by loadWorld().

#include <omnirange_sim/Geometry.h>
#include <omnirange_sim/Materials.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace omnirange::sim
{
/** A vertical prism: footprint extruded from z0 to z1. */
struct Solid
{
	Footprint footprint;
	double z0{0}, z1{2};  ///< [m]
	int material{0};  ///< index into World::materials
	int line{0};  ///< line of the world file that made it (for errors)
};

struct Light
{
	double azimuth{0.8};  ///< [rad] direction the sunlight comes from, in the world frame
	double elevation{0.9};  ///< [rad] above the horizon
	double ambient{0.45};  ///< [-] light everywhere, also in shadow
	double diffuse{0.65};  ///< [-] extra light on a surface facing the sun
	/** [-] how much darker the floor is right at the foot of a solid standing
	 * on it (ambient occlusion: the soft shadow at the base of walls and
	 * objects), fading over occlusion_radius [m]. */
	double occlusion{0.0};
	double occlusion_radius{0.15};  ///< [m]
};

/** A solid crossed by a 2D ray. */
struct SolidCrossing
{
	Crossing crossing;
	int solid;
};

class World
{
   public:
	std::string name;
	std::string file;  ///< where it was read from
	std::vector<std::string> maps;  ///< the grid-map files it names (`gridmap file=`), read with it: inputs too
	Vec2 lo{-10, -10}, hi{10, 10};  ///< [m] the map's extent
	int floor_material{0};
	std::vector<Material> materials;
	std::vector<Solid> solids;
	Light light;
	std::array<std::uint8_t, 3> sky_rgb{{200, 215, 235}};

	/** Builds the spatial index; call after the solids are final. */
	void buildIndex(double cell = 1.0);
	/** Every solid the ray origin + t dir crosses for t in (0, max_t),
	 * sorted by entry distance. `dir` is a unit vector. */
	void castRay(const Vec2& origin, const Vec2& dir, double max_t,
				 std::vector<SolidCrossing>& out) const;
	/** Material index by name, or -1. */
	int findMaterial(const std::string& name) const;

   private:
	double cell_{1.0};
	Vec2 grid_lo_;
	int nx_{0}, ny_{0};
	std::vector<std::vector<int>> grid_;  // solids overlapping each cell
};

/** [m] the largest |x| or |y| a world or route may use: the maps and the
 * renderer's shadow grid grow with the extent (a solid 1e6 m away once
 * asked for more memory than there is). */
constexpr double kMaxWorldCoordinate = 1000.0;
/** The most solids a world may have (a grid map's cells count one each): the
 * stock worlds have up to about 20,000; millions would take minutes a frame. */
constexpr std::size_t kMaxWorldSolids = 1000000;

/** Reads a world file; throws std::runtime_error "FILE:LINE: message". */
World loadWorld(const std::string& path);

}  // namespace omnirange::sim
