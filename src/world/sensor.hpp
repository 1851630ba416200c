#pragma once
/// @file sensor.hpp
/// Range sensor with optional field of view and seeded per-cell misses, in one of two physical
/// models (SensorParams::model): "grid" sees every cell in range that is in line of sight;
/// "beams" is a beam lidar (a fixed fan of rays, as in Stage and real laser scanners).
///
/// Grid model: visibility rule (precise, tested in tests/world/test_sensor.cpp):
/// - Range: a cell is in range when the Euclidean distance between the centres of the robot's
///   cell and the target cell is <= range_m / resolution_m (cells). The boundary is included.
/// - Field of view: with fov_deg < 360 the direction to the target cell centre must lie within
///   +-fov_deg/2 of the heading (inclusive). The robot's own cell is always seen.
/// - Rays: a ray is a segment from the centre of the robot's cell to an end point, walked cell
///   by cell (Amanatides-Woo, in exact integer arithmetic on doubled coordinates: cell x spans
///   [2x, 2x+2], its centre is at 2x+1). A ray is clear when every cell it enters strictly
///   before its end point, other than the target, is not occupied. Where it passes exactly
///   through a grid corner it touches the two cells beside the corner only at that point: it
///   is blocked there only if both of those cells are occupied (a diagonal gap between two
///   occupied cells is opaque; a gap with one free side is see-through).
/// - Free targets: visible when the centre ray (end point: the target's centre) is clear.
/// - Occupied targets: visible when the centre ray is clear, or a face ray is clear. A face
///   ray ends at the midpoint of a face of the target that looks toward the robot: with
///   dx = target.x - robot.x != 0, the vertical face on the robot's side (end point
///   x = 2*target.x + 1 - sign(dx), y = 2*target.y + 1); with dy != 0, the horizontal face on
///   the robot's side (likewise). The end point lies on the target's boundary, so the target
///   is only touched there and the last cell the ray enters is the one in front of that face,
///   which must be free. (A laser hits a wall's face, not its centre: along a straight wall,
///   a wall cell at a grazing angle is seen although its centre ray first enters the side of
///   its neighbour.) Face rays change only what is visible, not range or field of view, which
///   are still measured to the target's centre. Visibility is therefore symmetric between two
///   free cells but not in general when one of them is occupied.
///   Occupied cells that are visible are themselves observed.
/// - Noise: with miss_probability p > 0 every visible, still unknown cell stays unknown with
///   probability p on this scan (drawn from the run's "sensor" stream in a fixed cell order).
///
/// Beam model (tested in tests/world/test_beam_lidar.cpp; code in beam_lidar.hpp):
/// - Beams: n = `beams` rays. Beam i (i = 0..n-1) points at angle heading_rad + theta_i
///   (radians, clockwise on screen from +x, as heading_angle(); direction (cos, sin) in double
///   on the grid's (x, y)), with F = fov_deg in radians: for fov_deg < 360,
///   theta_i = F * (i / (n-1) - 1/2), so beam 0 is at -F/2 and beam n-1 at +F/2 (n = 1:
///   theta_0 = 0); for fov_deg = 360, theta_i = 2 pi (i - floor(n/2)) / n: evenly spaced,
///   without repeating beam 0, beam floor(n/2) on the heading.
/// - Traversal: in cells relative to the robot's cell centre (cell (x, y) spans
///   [x - 1/2, x + 1/2] x [y - 1/2, y + 1/2]), a beam starts at (0, 0) in the robot's own cell
///   and walks Amanatides-Woo in double arithmetic: it leaves cell (x, y) through its vertical
///   side at t_x = (|x| + 1/2) / |cos| and through its horizontal side at
///   t_y = (|y| + 1/2) / |sin| (t: distance along the beam in cells), whichever is smaller.
///   A ray from a cell centre never runs along a cell boundary. When |t_x - t_y| <= 1e-9 the
///   beam passes through the corner: it touches the two cells beside the corner only at that
///   point and is blocked there only when both are occupied (the grid model's corner rule);
///   then both are entered (first the one across the vertical side) and the beam ends.
///   Otherwise it moves on to the diagonal cell. Outside the map counts as occupied: a beam
///   ends at the map's edge (cells off the map are never revealed).
/// - Obstacles: the first occupied cell a beam enters is entered (revealed) and ends the beam.
///   The robot's own cell is entered by every beam and never blocks.
/// - Range: a beam is range_m / resolution_m cells long (the grid model's slack): it ends
///   before a boundary it would cross at t beyond that. Of the cells it enters, those in range
///   by the grid model's rule (centre to centre, inclusive) are seen: both models see inside
///   the same disc. Field of view: only through the beams' directions.
/// - Scan order: scan() reveals in beam order (0..n-1) and, along each beam, in the order the
///   beam enters cells; a cell seen by several beams counts at its first visit.
/// - Noise: with p > 0 each visited, still unknown cell other than the robot's is missed with
///   probability p on this scan: one draw from the "sensor" stream per such cell, at its first
///   visit, in scan order; a missed cell is not drawn again on this scan (it still stops a
///   beam if it is occupied).
/// - At long range, cells between two beams are not seen: fewer cells than the grid model.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <span>
#include <vector>

#include "core/params.hpp"
#include "core/random.hpp"
#include "world/beam_lidar.hpp"
#include "world/grid.hpp"
#include "world/known_map.hpp"
#include "world/scan_counts.hpp"
#include "world/world_map.hpp"

namespace fsweep {
inline namespace world {

/// True when the centre ray from the centre of `at` to the centre of `target` (cells of
/// `known`) is clear on the robot's own map: the grid model's ray rule (file comment above)
/// with known occupied cells as the only obstacles (unknown cells transparent, as
/// Sensor::gain()) and cells off the map as occupied. No range or field of view: the caller
/// decides those. `at` == `target`: true. For strategies that ask which cells are in view.
[[nodiscard]] bool centre_ray_clear(const KnownMap& known, Cell at, Cell target);

/// The disc of offsets in range (the range rule of the file comment above, its slack included)
/// of a sensor of `range_cells` cells, by rows: extent[u] for u in [0, r] is the largest v with
/// (u, v) in range (-1: none); both models see within it.
[[nodiscard]] std::vector<int> disc_extent(double range_cells);

/// The physical model of a Sensor (rules in the file comment above).
enum class SensorModel {
  Grid,   ///< "grid": every cell in range and in line of sight (exact shadowcasting)
  Beams,  ///< "beams": a beam lidar, `beams` rays over the field of view
};

struct SensorParams {
  /// Sensing radius (metres), > 0; for "beams" the beams' length.
  double range_m = 10.0;
  /// Field of view (degrees), in (0, 360]; 360 = omnidirectional. For "beams" the angle the
  /// beams are spread over, centred on the heading.
  double fov_deg = 360.0;
  /// Probability that a visible unknown cell is missed on one scan, in [0, 1).
  double miss_probability = 0.0;
  /// The physical model.
  SensorModel model = SensorModel::Grid;
  /// Number of beams, in [1, kMaxBeams]; used only by SensorModel::Beams.
  int beams = 360;
  friend bool operator==(const SensorParams&, const SensorParams&) = default;
};

/// Most beams a sensor may have (declared upper bound of `beams`).
inline constexpr int kMaxBeams = 100000;

/// The declared parameters (core/params.hpp): range_m, fov_deg, miss_probability, model, beams.
[[nodiscard]] const ParamDecl<SensorParams>& sensor_params();
/// sensor_params().read(j, where): every problem at its JSON path, as one ConfigError.
[[nodiscard]] SensorParams sensor_params_from_json(const nlohmann::json& j, const std::string& where);
/// sensor_params().write(p) without `model` and `beams` while they hold their defaults, so that
/// the recorded JSON (run keys, runs.csv columns) of a grid sensor is what it was before the
/// beam model existed.
void to_json(nlohmann::json& j, const SensorParams& p);

/// What a grid sensor sees from each cell of one true map: for every cell, one bit per offset in
/// range (by rank, the offset-table order) for each target in line of sight on that map,
/// whatever the robot knows; the field of view and the noise apply at each scan. Scans fill it
/// cell by cell, the first time a scan from a cell has an unknown cell in range that some scan
/// could see (Sensor::scan's `observable`), so the
/// runs of one map and their forks, which scan from the same cells again and again (the weight
/// search runs thousands of them), sweep each cell once. Several threads may scan with one
/// table at once. Made by Sensor::sight_table(); a scan with it reveals the same cells in the
/// same order with the same noise draws as one without.
class SightTable {
 public:
  /// True when the targets seen from cell `index` (an index of the map, 0 <= index < width x
  /// height) are in the table.
  [[nodiscard]] bool filled(int index) const {
    return state_[static_cast<std::size_t>(index)].load(std::memory_order_acquire) == kFilled;
  }
  /// The table's size in bytes (most of it is touched only for cells scans fill).
  [[nodiscard]] std::size_t bytes() const { return bytes_for(cells_, words_ * 64); }
  /// The size of a table of `cells` cells for a disc of `offsets` offsets (the largest size_t
  /// when that overflows).
  [[nodiscard]] static std::size_t bytes_for(std::size_t cells, std::size_t offsets);

 private:
  friend class Sensor;
  /// An empty table for `map` (which must outlive it) and a grid sensor of `range_cells` cells
  /// whose disc has `offsets` offsets in range (Sensor::sight_table(), which checks its size).
  SightTable(const WorldMap& map, double range_cells, std::size_t offsets);
  static constexpr std::uint8_t kEmpty = 0;
  static constexpr std::uint8_t kFilling = 1;  // one thread fills it; the others sweep for themselves
  static constexpr std::uint8_t kFilled = 2;

  const WorldMap* map_;
  double range_cells_;
  std::size_t cells_;
  std::size_t words_;                                   // 64-bit words per cell
  std::unique_ptr<std::atomic<std::uint8_t>[]> state_;  // per cell: kEmpty, kFilling or kFilled
  std::unique_ptr<std::uint64_t[]> bits_;               // per cell: words_ words, valid once kFilled
};

/// A sensor for one resolution, of either model. Grid: precomputes the offsets in range in
/// offset-table order (O(r^2) memory for a range of r cells, at most 2000 cells); a scan sweeps
/// the eight octants around the robot by exact shadowcasting, so its cost follows the cells
/// that can be seen. Beams: set-up O(beams), a scan O(beams x r) (BeamLidar). Copyable value
/// type: copies share the immutable tables and each has its own result buffers (so one
/// instance must not scan from two threads at once, nor, with the beam model, call gain(); but
/// copies may).
class Sensor {
 public:
  /// Largest supported range (cells): the tables grow with its square (about 115 MB at 2000
  /// cells, 215 MB with a limited field of view). RunSetup refuses longer ranges.
  static constexpr int kMaxRangeCells = 2000;

  /// Largest range (cells, rounded down) at which scan() first checks for a disc without
  /// obstacles, where every target is visible and no sweep is needed: beyond it that O(r^2)
  /// check could cost more than a sweep among walls, which follows the cells it sees.
  static constexpr int kOpenDiscMaxCells = 8;

  /// Largest SightTable sight_table() makes (bytes): 256 MiB, a 241 x 241 map at 6 cells of range
  /// takes about 1 MB, a 2,000 x 2,000 one at 30 cells 1.4 GB (no table then).
  static constexpr std::size_t kMaxSightTableBytes = std::size_t{256} << 20;

  Sensor() = default;
  Sensor(const SensorParams& params, double resolution_m);

  /// Scans from `at` facing `heading_rad` (radians, clockwise on screen from +x, as
  /// heading_angle()). Reveals visible unknown cells of `truth` into `known` and returns the
  /// indices of the cells revealed by this scan: grid model in increasing offset-table order,
  /// beam model in scan order (beam by beam, along each beam). The span stays valid until the
  /// next call. `rng` is used only when miss_probability > 0.
  ///
  /// `observable` (optional, grid model): per cell of `truth`, 0 when no scan from where the robot
  /// can stand ever sees it (the inside of a building: RunSetup::observable). A scan whose range
  /// holds no unknown cell but such ones reveals nothing and is skipped, as one whose range is all
  /// known; the cells revealed are the same either way.
  ///
  /// `sight` (optional, grid model): the SightTable of this `truth` object for a sensor of this
  /// range, read for cells it holds and filled for the others (std::invalid_argument when it was
  /// made for another map object or range). The cells revealed are the same with it and without.
  std::span<const int> scan(const WorldMap& truth, KnownMap& known, Cell at, double heading_rad, Rng& rng,
                            const std::uint8_t* observable = nullptr, SightTable* sight = nullptr);

  /// An empty SightTable for scans of `truth` (which must outlive it) by this sensor, its copies,
  /// or any grid sensor of the same range; null for the beam model, a default-constructed
  /// sensor, or a table larger than kMaxSightTableBytes.
  [[nodiscard]] std::unique_ptr<SightTable> sight_table(const WorldMap& truth) const;

  /// What a scan from `at` facing `heading_rad` would see on the robot's own map `known`, for
  /// information-gain estimates (Holz 2010 section IV-B/C): the same range, field of view and
  /// ray rules as scan(), with known occupied cells as the only obstacles (unknown cells are
  /// transparent). Known free and unknown targets need their centre ray clear; known occupied
  /// targets their centre ray or a face ray (an unknown target is not assumed to be a wall).
  /// Beam model: the same beams as scan(), stopped by known occupied cells (which are counted)
  /// and the map's edge; each cell once. Noise is ignored. Cells off the map are not counted.
  /// `at` off the map: both counts 0. Uses the same walk as scan(); does not change the maps.
  [[nodiscard]] ScanCounts gain(const KnownMap& known, Cell at, double heading_rad) const;

  /// True when `target` is visible from `at` on `truth`, noise ignored. Grid model: the range
  /// and ray rules (field of view and heading ignored), walking the rays directly,
  /// independently of the sweep. Beam model: a scan from `at` facing `heading_rad` would
  /// reveal it (beams turn with the heading). For tests and for information-gain estimates.
  [[nodiscard]] bool visible(const WorldMap& truth, Cell at, Cell target, double heading_rad) const;
  /// visible() facing heading 0 (east): the grid model's rule, which ignores the heading.
  [[nodiscard]] bool visible(const WorldMap& truth, Cell at, Cell target) const {
    return visible(truth, at, target, 0.0);
  }

  [[nodiscard]] const SensorParams& params() const { return params_; }
  /// Sensing radius in cells.
  [[nodiscard]] double range_cells() const { return range_cells_; }

 private:
  struct Tables;  // defined in sensor.cpp; immutable once built

  /// The one sweep behind scan() and gain(), on a width x height grid: for each target in range
  /// that is on the grid, not skip(index), inside the field of view and in line of sight with
  /// opaque(index) as the obstacle test (for crossed cells and for choosing the occupied-target
  /// rule), calls visit(index, rank) once, rank being its position in offset-table order (the
  /// robot's own cell has rank 0). `whole_disc`: every direction, the field of view ignored.
  /// The order of the calls is unspecified. Defined in sensor.cpp, the only place it is used.
  template <typename Skip, typename Opaque, typename Visit>
  void for_each_visible(int width, int height, Cell at, double heading_rad, bool whole_disc, Skip&& skip,
                        Opaque&& opaque, Visit&& visit) const;

  /// The targets seen from `at` on `truth` as bits by rank (SightTable's row): `sight`'s row,
  /// swept and filled first when empty (or swept into a scratch row while another thread fills it).
  const std::uint64_t* sight_row(SightTable& sight, const WorldMap& truth, Cell at);
  /// Half the field of view (radians) with the rounding slack: a target farther off the heading
  /// is not seen.
  [[nodiscard]] double half_field_of_view() const;
  /// True when the target of rank `rank` lies outside the field of view facing `heading_rad`
  /// (never the robot's own cell). Only for a field of view below 360 degrees (the tables have
  /// angles then).
  [[nodiscard]] bool outside_view(std::uint32_t rank, double heading_rad) const;
  /// Reveals into `known`, in rank order, the targets of `bits` (words [first_word, end_word)),
  /// with scan()'s noise draws, and appends them to revealed_. kEveryTarget: `bits` holds every
  /// target seen (a SightTable row), and only those unknown and in the field of view are taken;
  /// otherwise it holds only those.
  template <bool kEveryTarget>
  void reveal_ranks(const WorldMap& truth, KnownMap& known, Cell at, double heading_rad, Rng& rng,
                    const std::uint64_t* bits, std::size_t first_word, std::size_t end_word);

  /// True when every cell within range of `at` on the map is known, or 0 in `observable` (may be
  /// null: every cell may be seen) (scan() has nothing to do).
  [[nodiscard]] bool all_known(const KnownMap& known, Cell at, const std::uint8_t* observable) const;
  /// True when no cell within range of `at` on `truth` is occupied (kOpenDiscMaxCells).
  [[nodiscard]] bool open_disc(const WorldMap& truth, Cell at) const;

  SensorParams params_;
  double range_cells_ = 0.0;
  std::shared_ptr<const Tables> tables_;  // null for a default-constructed sensor and for beams
  BeamLidar beams_;                       // the beam model; empty for the grid model
  std::vector<int> revealed_;
  /// Scratch of scan(): one bit per offset in range, by rank; all zero between scans.
  std::vector<std::uint64_t> seen_bits_;
  /// Scratch of sight_row() while another thread fills the table's row.
  std::vector<std::uint64_t> sight_scratch_;
};

}  // namespace world
}  // namespace fsweep
