# Per-target warnings (never global flags), as in STYLE.md.
function(hrgbd_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wshadow -Wno-psabi)
endfunction()

# A project library: modules/<name>/{include,src}.
function(hrgbd_module name)
  file(GLOB srcs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp)
  add_library(${name} STATIC ${srcs})
  target_include_directories(${name} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
  hrgbd_warnings(${name})
endfunction()
