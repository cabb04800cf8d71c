// readSetting("N") lowers to texcc_setting_N(texcc_ctx).
// RUN: texcc-fe %s | FileCheck %s

float f(void) {
  // CHECK: {{^}}  float t = texcc_setting_Time(texcc_ctx);
  float t = readSetting("Time");
  // CHECK: {{^}}  int frame = texcc_setting_Frame(texcc_ctx);
  int frame = readSetting("Frame");
  // CHECK: {{^}}  float3 cam = texcc_setting_CameraPos(texcc_ctx);
  float3 cam = readSetting("CameraPos");
  return t + frame + cam.x;
}
