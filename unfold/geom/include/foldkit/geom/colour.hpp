#pragma once
// A colour as data: what a model's material or a sheet's fill says, not how a renderer draws a role.
namespace foldkit {

/// Linear components in [0, 1] as the file gives them (OBJ Kd, glTF baseColorFactor, PLY bytes / 255).
struct Colour {
  double r = 1, g = 1, b = 1;
  friend constexpr bool operator==(Colour a, Colour b) = default;
};

}  // namespace foldkit
