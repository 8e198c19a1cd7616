#include "rgbd_odometry/GeometricFeatures.h"

#include <memory>

#include "rgbd_odometry/FrameResult.h"
#include "rgbd_odometry/Is3dSampling.h"
#include "rgbd_odometry/PointCloud.h"
#include "rgbd_odometry/ShotDescriptor.h"

namespace hrgbd {

GeometricFeatures extractGeometricFeatures(const RgbdImage& image, const GeometricParams& p) {
  GeometricFeatures out;
  out.features.descriptors.create(0, kShotLength, CV_32F);

  // III-C
  DownsampledCloud cloud = timed(out.ms_downsample, [&] { return downsampleDepth(image, p); });
  out.cloud_points = cloud.input_points;
  out.downsampled_points = cloud.points.size();
  out.radius = cloud.radius;
  if (cloud.points.size() < 3) return out;

  // III-D (the k-d tree, also used by SHOT, counts with the normals)
  const auto tree =
      timed(out.ms_normals, [&] { return std::make_unique<PointKdTree>(cloud.points); });
  Points normals = timed(out.ms_normals, [&] {
    return estimateNormals(cloud.points, *tree, p.normal_radius_factor * cloud.radius);
  });
  const Is3dResult is3d = timed(out.ms_is3d, [&] { return sampleIs3d(normals, p); });  // III-E
  out.is3d_candidates = is3d.candidates;
  out.dominant_orientations = is3d.groups.size();
  ShotResult shot = timed(out.ms_shot, [&] {  // III-F
    return computeShot(cloud.points, normals, *tree, is3d.indices,
                       p.shot_radius_factor * cloud.radius, p.shot_min_neighbours);
  });
  out.features.descriptors = shot.descriptors;
  out.features.detected = is3d.indices.size();
  for (const std::size_t i : shot.kept)
    out.features.points.push_back(cloud.points[i].cast<double>());
  out.cloud = std::move(cloud.points);
  out.normals = std::move(normals);
  return out;
}

}  // namespace hrgbd
