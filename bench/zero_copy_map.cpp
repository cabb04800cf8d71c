// Zero-copy check for the Embree trace backend (docs/runtime.md, Trace backends): on the first
// OpenCL device, map+unmap of a 16 MiB buffer (READ|WRITE) against a read+write copy of it.
// Build and run: g++ -O2 -std=c++17 bench/zero_copy_map.cpp -o /tmp/zc -lOpenCL && /tmp/zc
#define CL_HPP_TARGET_OPENCL_VERSION 120
#define CL_HPP_MINIMUM_OPENCL_VERSION 120
#define CL_HPP_ENABLE_EXCEPTIONS
#include <CL/opencl.hpp>
#include <chrono>
#include <cstdio>
#include <vector>
static double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
int main() {
  std::vector<cl::Platform> P; cl::Platform::get(&P);
  std::vector<cl::Device> D; P[0].getDevices(CL_DEVICE_TYPE_ALL, &D);
  cl::Context Ctx(D[0]); cl::CommandQueue Q(Ctx, D[0]);
  printf("device %s\n", D[0].getInfo<CL_DEVICE_NAME>().c_str());
  const size_t Bytes = 262144 * 64; // paths of one 512x512 pass (RtPath: 80 bytes -> use 64 MiB-ish)
  for (cl_mem_flags F : {cl_mem_flags(CL_MEM_READ_WRITE), cl_mem_flags(CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR)}) {
    cl::Buffer B(Ctx, F, Bytes);
    std::vector<char> Host(Bytes, 1);
    Q.enqueueWriteBuffer(B, CL_TRUE, 0, Bytes, Host.data());
    void *First = nullptr; bool Same = true;
    const int N = 50;
    double T0 = now();
    for (int I = 0; I < N; ++I) {
      void *Ptr = Q.enqueueMapBuffer(B, CL_TRUE, CL_MAP_READ | CL_MAP_WRITE, 0, Bytes);
      if (!First) First = Ptr; else Same &= Ptr == First;
      ((char *)Ptr)[I] += 1;
      Q.enqueueUnmapMemObject(B, Ptr); Q.finish();
    }
    double Map = (now() - T0) / N;
    T0 = now();
    for (int I = 0; I < N; ++I) { Q.enqueueReadBuffer(B, CL_TRUE, 0, Bytes, Host.data()); Q.enqueueWriteBuffer(B, CL_TRUE, 0, Bytes, Host.data()); }
    double Copy = (now() - T0) / N;
    printf("%s: %zu MiB: map+unmap %.1f us (same pointer each time: %d); read+write copy %.1f us\n",
           F & CL_MEM_ALLOC_HOST_PTR ? "ALLOC_HOST_PTR" : "READ_WRITE", Bytes >> 20, Map * 1e6, Same, Copy * 1e6);
  }
}
