// Every scheme with the wendland_c2 kernel, in 2D and 3D (see kernel_schemes.hpp).
#include "flume/kernels/wendland_c2.hpp"
#include "flume/schemes/kernel_schemes_impl.hpp"

FLUME_KERNEL_SCHEMES(flume::WendlandC2);
