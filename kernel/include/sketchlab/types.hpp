#pragma once
// Basic numeric types shared by the whole kernel. Units: metres for workspace
// positions, seconds for times, pixels for 2D stroke positions.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>

namespace sketchlab {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Vec4 = Eigen::Vector4d;
using Mat3 = Eigen::Matrix3d;
using Mat4 = Eigen::Matrix4d;
using Quat = Eigen::Quaterniond;
using Box3 = Eigen::AlignedBox3d;

using StrokeId = std::uint64_t;
using CurveId = std::uint64_t;
using NodeId = std::uint64_t;
using PatchId = std::uint64_t;

}  // namespace sketchlab
