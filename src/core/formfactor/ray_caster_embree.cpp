// The Embree 3 back end of RayScene (ray_caster.h); compiled to a stub where the build has no Embree.
#include "core/formfactor/ray_caster.h"

#if RT_HAVE_EMBREE

#include <embree3/rtcore.h>

#include <stdexcept>

namespace rt {
namespace {

// The context Embree hands to the filter.
struct FilterContext {
  RTCIntersectContext base;
  const RayFilter* filter;
};

void applyFilter(const RTCFilterFunctionNArguments* args) {
  const auto* context = reinterpret_cast<const FilterContext*>(args->context);
  for (unsigned k = 0; k < args->N; ++k) {
    if (args->valid[k] == 0) continue;
    const unsigned primitive = RTCHitN_primID(args->hit, args->N, k);
    if (!context->filter->accepts(primitive, RTCRayN_dir_x(args->ray, args->N, k),
                                  RTCRayN_dir_y(args->ray, args->N, k), RTCRayN_dir_z(args->ray, args->N, k)))
      args->valid[k] = 0;
  }
}

RTCRay toEmbree(const FloatRay& ray) {
  RTCRay out{};
  out.org_x = ray.origin[0];
  out.org_y = ray.origin[1];
  out.org_z = ray.origin[2];
  out.dir_x = ray.direction[0];
  out.dir_y = ray.direction[1];
  out.dir_z = ray.direction[2];
  out.tnear = ray.tnear;
  out.tfar = ray.tfar;
  out.mask = 0xFFFFFFFFu;
  out.flags = 0;
  return out;
}

class EmbreeCaster final : public RayCaster {
 public:
  EmbreeCaster(const std::vector<float>& vertices, const std::vector<unsigned>& triangles) {
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw std::runtime_error("Embree: cannot create a device");
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertices.size() / 3));
    std::copy(vertices.begin(), vertices.end(), v);
    auto* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangles.size() / 3));
    std::copy(triangles.begin(), triangles.end(), t);
    rtcSetGeometryIntersectFilterFunction(geometry, applyFilter);
    rtcSetGeometryOccludedFilterFunction(geometry, applyFilter);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene_);
  }
  ~EmbreeCaster() override {
    if (scene_) rtcReleaseScene(scene_);
    if (device_) rtcReleaseDevice(device_);
  }
  EmbreeCaster(const EmbreeCaster&) = delete;
  EmbreeCaster& operator=(const EmbreeCaster&) = delete;

  bool occluded(const FloatRay& ray, const RayFilter& filter) const override {
    FilterContext context;
    rtcInitIntersectContext(&context.base);
    context.filter = &filter;
    RTCRay query = toEmbree(ray);
    rtcOccluded1(scene_, &context.base, &query);
    return query.tfar < 0;  // Embree sets tfar to -inf on a hit
  }

  int nearest(const FloatRay& ray, const RayFilter& filter, float& t) const override {
    FilterContext context;
    rtcInitIntersectContext(&context.base);
    context.filter = &filter;
    RTCRayHit query{};
    query.ray = toEmbree(ray);
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    query.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context.base, &query);
    if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return -1;
    t = query.ray.tfar;
    return static_cast<int>(query.hit.primID);
  }

 private:
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

}  // namespace

std::unique_ptr<RayCaster> makeEmbreeCaster(const std::vector<float>& vertices,
                                            const std::vector<unsigned>& triangles) {
  return std::make_unique<EmbreeCaster>(vertices, triangles);
}

}  // namespace rt

#else

namespace rt {

std::unique_ptr<RayCaster> makeEmbreeCaster(const std::vector<float>&, const std::vector<unsigned>&) {
  return nullptr;
}

}  // namespace rt

#endif
