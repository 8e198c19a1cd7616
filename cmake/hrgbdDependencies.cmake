# The packages the hrgbd libraries link against. Included by the top-level CMakeLists.txt and by
# the installed hrgbdConfig.cmake, so the build and its consumers resolve the same imported
# targets (mrpt::*, opencv_*, Open3D::Open3D, Eigen3::Eigen, nanoflann::nanoflann, JPEG::JPEG,
# PkgConfig::OPENNI2, PkgConfig::PLPLOT, ZLIB::ZLIB). The includer defines hrgbd_dependency(<find_package arguments>):
# find_package(... REQUIRED) in the build, find_dependency() in the package config.
hrgbd_dependency(mrpt-obs)
hrgbd_dependency(mrpt-maps)
hrgbd_dependency(mrpt-tfest)
hrgbd_dependency(mrpt-hwdrivers)
hrgbd_dependency(mrpt-gui)
hrgbd_dependency(mrpt-slam)
hrgbd_dependency(mrpt-graphslam)
hrgbd_dependency(OpenCV 4 COMPONENTS core imgproc features2d imgcodecs calib3d rgbd)
# Open3D's dense odometry (rgbd_baselines' open3d_* peers; 0.16 in Debian 12).
hrgbd_dependency(Open3D)
hrgbd_dependency(Eigen3 3.3 NO_MODULE)
hrgbd_dependency(nanoflann)
hrgbd_dependency(JPEG)
hrgbd_dependency(ZLIB)
hrgbd_dependency(PkgConfig)
# The includer checks for the targets PkgConfig::OPENNI2 and PkgConfig::PLPLOT.
pkg_check_modules(OPENNI2 IMPORTED_TARGET libopenni2)
# PLplot draws rgbd_eval's plots (Debian: libplplot-dev; its cairo driver writes PNG, SVG, PDF).
pkg_check_modules(PLPLOT IMPORTED_TARGET plplot)
