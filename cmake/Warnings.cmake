# Per-target warnings (never global flags), as in STYLE.md.
function(hrgbd_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wshadow -Wno-psabi)
endfunction()

# A project library: modules/<name>/{include,src}, also reachable as hrgbd::<name> (the name
# consumers of the installed package use), installed and exported (cmake/Package.cmake).
function(hrgbd_module name)
  file(GLOB srcs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp)
  add_library(${name} STATIC ${srcs})
  add_library(hrgbd::${name} ALIAS ${name})
  target_include_directories(${name} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
                                            $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  # Consumers of the installed package get C++17 without setting it themselves.
  target_compile_features(${name} PUBLIC cxx_std_17)
  hrgbd_warnings(${name})
  hrgbd_install_library(${name})
endfunction()
