// Every scheme with the cubic_spline kernel, in 2D and 3D (see kernel_schemes.hpp).
#include "flume/kernels/cubic_spline.hpp"
#include "flume/schemes/kernel_schemes_impl.hpp"

FLUME_KERNEL_SCHEMES(flume::CubicSpline);
