#pragma once
/** \file Timing.h
 * The one timing helper of the project: stage times are measured by wrapping the stage. */
#include <chrono>

namespace hrgbd {

/** Runs `f()` and adds its duration [ms] to `acc`; returns what `f` returns. */
template <class F>
auto timed(double& acc, F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  struct Add {  // adds on every exit, also when f() throws
    double& acc;
    std::chrono::steady_clock::time_point t0;
    ~Add() {
      acc +=
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    }
  } add{acc, t0};
  return f();
}

}  // namespace hrgbd
