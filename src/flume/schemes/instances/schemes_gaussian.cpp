// Every scheme with the gaussian kernel, in 2D and 3D (see kernel_schemes.hpp).
#include "flume/kernels/gaussian.hpp"
#include "flume/schemes/kernel_schemes_impl.hpp"

FLUME_KERNEL_SCHEMES(flume::Gaussian);
