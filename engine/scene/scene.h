// A scene as its file describes it (INTERFACE.md, "Scene file"): every key, with the defaults
// filled in. scene_loader.h reads and validates it; scene_world.h builds the World from it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/types.h"
#include "engine/dynamics/material.h"
#include "engine/geometry/rugosity_pattern.h"

namespace rugosim {

// The defaults of the scene format, in one place (docs/scene-format.md lists them too).
struct SceneDefaults {
  static constexpr double kGravityY = -9.81;  // m/s²
  static constexpr std::uint64_t kSeed = 0;
  static constexpr double kQ = 0.9;               // λ = q·σ
  static constexpr double kFrictionGain = 100.0;  // 1/m
  static constexpr double kBlobIrregularity = 0.4;
  static constexpr std::size_t kSegments = 32;    // for generated shapes without "segments"
  static constexpr int kWidth = 1280;             // px
  static constexpr int kHeight = 720;             // px
  static constexpr double kFps = 30.0;            // frames per second
  static constexpr const char* kBackground = "";  // the theme's ("paper": "#f4f1ea")
  static constexpr const char* kTheme = "paper";
  static constexpr const char* kAccuracy = "normal";
};

enum class ShapeKind { kControlPoints, kCircle, kEllipse, kBox, kBlob, kPolygon };

struct ShapeSpec {
  ShapeKind kind = ShapeKind::kControlPoints;
  std::vector<Vec2> control_points;  // m, body frame (kControlPoints; kPolygon: its corners)
  std::vector<double> rounding;      // m, kPolygon: one per corner, or empty (all sharp)
  double radius = 0.0;               // m (circle, blob)
  Vec2 radii = Vec2::Zero();         // m (ellipse)
  Vec2 size = Vec2::Zero();          // m, width and height (box)
  double irregularity = SceneDefaults::kBlobIrregularity;  // blob, in [0, 0.9]
  std::uint64_t seed = 0;                                  // blob outline
  std::size_t segments = SceneDefaults::kSegments;         // generated shapes
};

// σ per segment: one value for all, a list with one per segment, or a pattern scaled by sigma.
struct RugositySpec {
  std::optional<RugosityPattern> pattern;
  std::vector<double> sigma;  // m: empty (σ = 0), one value, or one per segment
};

struct BodySpec {
  std::string name;
  bool fixed = false;
  ShapeSpec shape;
  Vec2 position = Vec2::Zero();   // m, the body frame's origin
  double angle = 0.0;             // rad
  Vec2 velocity = Vec2::Zero();   // m/s
  double angular_velocity = 0.0;  // rad/s
  Material material;
  std::string material_name;  // the name in "materials", empty for an inline or default one
  RugositySpec rugosity;
  std::string color;  // "#rrggbb" or "#rgb" to draw it with; empty: the default palette
};

struct CameraSpec {
  bool automatic = true;       // "auto": fit every body over the whole clip
  Vec2 center = Vec2::Zero();  // m
  double height = 0.0;         // m, of the visible world; with `follow`, 0 for 4 × its size
  // A body's name: the view is centred on its centre of mass in every frame (not automatic).
  std::string follow;
};

// render.background for frames without a background (alpha 0 where no body is): PNG, GIF,
// WebM, MOV and WebP keep it; an MP4 cannot.
inline constexpr const char* kTransparentBackground = "transparent";

// A corner of the frame, for the clock and the scale bar: "top-left", "top-right",
// "bottom-left", "bottom-right".
inline constexpr const char* kCorners[] = {"top-left", "top-right", "bottom-left", "bottom-right"};

// render.clock: the frame's time, written with `format` (one printf conversion %f or %.Nf).
struct ClockSpec {
  std::string corner = "top-left";
  std::string format = "t = %.2f s";
};

// render.scale_bar: a bar of `length` m (0: the longest of 1, 2 or 5 × 10^k m within a fifth of
// the frame's width), labelled.
struct ScaleBarSpec {
  std::string corner = "bottom-left";
  double length = 0.0;  // m
};

// render.colour_bar: the rugosity overlay's colours, 0 to the scene's largest λ, labelled.
struct ColourBarSpec {
  std::string corner = "bottom-right";
};

struct RenderSpec {
  int width = SceneDefaults::kWidth;
  int height = SceneDefaults::kHeight;
  double fps = SceneDefaults::kFps;
  CameraSpec camera;
  std::string theme = SceneDefaults::kTheme;  // "paper", "dark" or "print"
  // "#rrggbb", kTransparentBackground, or "" for the theme's.
  std::string background = SceneDefaults::kBackground;
  std::string outline_color;   // "#rrggbb" for every outline; "" for the theme's
  double outline_width = 0.0;  // px at 720 lines (scaled with the frame); 0 for 1.5
  // Display-only: the drawn rugosity detail's amplitude × roughness_scale, and its correlation
  // length (m; 0 for 4 × the body's largest σ × roughness_scale). The physics never sees them.
  double roughness_scale = 1.0;
  double roughness_length = 0.0;
  std::vector<std::string> overlays;
  std::string title;    // drawn at the top, centred ("" for none)
  std::string caption;  // drawn at the bottom, centred ("" for none)
  std::optional<ClockSpec> clock;
  std::optional<ScaleBarSpec> scale_bar;
  std::optional<ColourBarSpec> colour_bar;  // drawn while the rugosity overlay is
};

// world.accuracy: a preset ("draft", "normal", "precise") and knobs that override it, by the
// keys of accuracy_knobs() (engine/dynamics/accuracy.h).
struct AccuracySpec {
  std::string preset = SceneDefaults::kAccuracy;
  std::map<std::string, double> knobs;
};

struct Scene {
  int version = 1;
  std::string name;
  Vec2 gravity = Vec2(0.0, SceneDefaults::kGravityY);
  double duration = 0.0;  // s, > 0
  std::uint64_t seed = SceneDefaults::kSeed;
  AccuracySpec accuracy;
  double q = SceneDefaults::kQ;
  double friction_gain = SceneDefaults::kFrictionGain;
  std::map<std::string, Material> materials;
  std::vector<BodySpec> bodies;
  RenderSpec render;
};

}  // namespace rugosim
