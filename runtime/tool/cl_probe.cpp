// texcc-cl-probe: prints one line per OpenCL device; exits 1 when there is none.
#include <CL/opencl.hpp>

#include <cstdio>
#include <vector>

int main() {
  std::vector<cl::Platform> Platforms;
  if (cl::Platform::get(&Platforms) != CL_SUCCESS || Platforms.empty()) {
    std::fprintf(stderr, "texcc-cl-probe: no OpenCL platform found\n");
    return 1;
  }
  int Count = 0;
  for (auto &P : Platforms) {
    std::vector<cl::Device> Devices;
    if (P.getDevices(CL_DEVICE_TYPE_ALL, &Devices) != CL_SUCCESS)
      continue;
    for (auto &D : Devices)
      std::printf("%d: %s (%s)\n", Count++, D.getInfo<CL_DEVICE_NAME>().c_str(),
                  P.getInfo<CL_PLATFORM_NAME>().c_str());
  }
  if (Count == 0) {
    std::fprintf(stderr, "texcc-cl-probe: no OpenCL device found\n");
    return 1;
  }
  return 0;
}
