#include "rgbd_odometry/GeometricFeatures.h"

#include "Stopwatch.h"
#include "rgbd_odometry/Is3dSampling.h"
#include "rgbd_odometry/PointCloud.h"
#include "rgbd_odometry/ShotDescriptor.h"

namespace hrgbd {

GeometricFeatures extractGeometricFeatures(const RgbdImage& image, const GeometricParams& p) {
  GeometricFeatures out;
  out.features.descriptors.create(0, kShotLength, CV_32F);

  auto t0 = Clock::now();  // III-C
  DownsampledCloud cloud = downsampleDepth(image, p);
  out.cloud_points = cloud.input_points;
  out.downsampled_points = cloud.points.size();
  out.radius = cloud.radius;
  out.ms_downsample = msSince(t0);
  if (cloud.points.size() < 3) return out;

  t0 = Clock::now();  // III-D
  const PointKdTree tree(cloud.points);
  Points normals = estimateNormals(cloud.points, tree, p.normal_radius_factor * cloud.radius);
  out.ms_normals = msSince(t0);

  t0 = Clock::now();  // III-E, Algorithm 1
  const Is3dResult is3d = sampleIs3d(normals, p);
  out.is3d_candidates = is3d.candidates;
  out.dominant_orientations = is3d.groups.size();
  out.ms_is3d = msSince(t0);

  t0 = Clock::now();  // III-F
  ShotResult shot = computeShot(cloud.points, normals, tree, is3d.indices,
                                p.shot_radius_factor * cloud.radius, p.shot_min_neighbours);
  out.features.descriptors = shot.descriptors;
  out.features.detected = is3d.indices.size();
  for (const std::size_t i : shot.kept)
    out.features.points.push_back(cloud.points[i].cast<double>());
  out.ms_shot = msSince(t0);
  out.cloud = std::move(cloud.points);
  out.normals = std::move(normals);
  return out;
}

}  // namespace hrgbd
