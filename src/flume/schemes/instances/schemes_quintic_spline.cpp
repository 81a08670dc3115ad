// Every scheme with the quintic_spline kernel, in 2D and 3D (see kernel_schemes.hpp).
#include "flume/kernels/quintic_spline.hpp"
#include "flume/schemes/kernel_schemes_impl.hpp"

FLUME_KERNEL_SCHEMES(flume::QuinticSpline);
