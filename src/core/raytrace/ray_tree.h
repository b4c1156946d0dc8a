// The rays one pixel's sample sends, as data: the primary ray from the eye, the shadow rays from every
// surface it reaches towards every light, and the mirror rays that carry the recursion on. The figures draw
// it in the scene, and the counts by kind are what the cost formula (core/raytrace/ray_cost.h) predicts.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/vec.h"

namespace rt {

enum class RayKind { Primary, Shadow, Reflection };
std::string toString(RayKind kind);

struct RayCounts {
  std::uint64_t primary = 0, shadow = 0, reflection = 0;
  std::uint64_t total() const { return primary + shadow + reflection; }
  RayCounts& operator+=(const RayCounts& other) {
    primary += other.primary;
    shadow += other.shadow;
    reflection += other.reflection;
    return *this;
  }
};

struct RayNode {
  RayKind kind = RayKind::Primary;
  int parent = -1;  // index of the ray whose hit sent it (-1: the primary ray)
  int depth = 0;    // mirror reflections before it
  Vec3 origin = Vec3::Zero();
  Vec3 end = Vec3::Zero();  // the hit, the point on the light, the blocker, or a point along an escaped ray
  int element = -1;         // the element it reached first (-1: none; shadow rays: the blocker)
  bool blocked = false;     // shadow rays: something lies between the surface and the light
};

struct RayTree {
  std::vector<RayNode> nodes;
  RayCounts counts() const;
};

}  // namespace rt
