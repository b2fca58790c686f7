#pragma once
// Ceres reports failed evaluations through glog on stderr ("Logging before
// InitGoogleLogging() ...", "Terminating: Residual and Jacobian evaluation
// failed"); procsim reports its own outcome in one line, so glog is kept
// quiet.  Header-only: a model that uses Ceres links it (and glog) itself.
#include <ceres/ceres.h>

namespace procsim
{

inline void quietCeres()
{
    FLAGS_minloglevel = google::GLOG_FATAL;
}

} // namespace procsim
