// polyDEM CUDA back end: the same Thrust engine compiled by nvcc.
#define PD_BACKEND_NAME "cuda"
#define PD_BACKEND_NS cuda

#include "ThrustEngine.inl"

#include <cuda_runtime.h>

#include <string>

extern "C" __attribute__((visibility("default"))) polydem::Engine* polydemCreateEngine()
{
    int count = 0;
    const cudaError_t err = cudaGetDeviceCount(&count);
    if (err != cudaSuccess || count == 0)
    {
        throw polydem::Error
        (
            std::string("no usable CUDA device (") + cudaGetErrorString(err)
          + "): use 'device cpu;' on this machine",
            "", "device"
        );
    }
    return new polydem::cuda::ThrustEngine();
}
