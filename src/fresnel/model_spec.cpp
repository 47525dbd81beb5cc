#include "fresnel/model_spec.h"

namespace fl::fresnel {

std::vector<std::string> ModelSpec::param_names() const {
  std::vector<std::string> out;
  for (const char* c : {"r", "g", "b"})
    for (const auto& p : channel_params) out.push_back(std::string(p.name) + "_" + c);
  for (const auto& p : shared_params) out.push_back(p.name);
  return out;
}

std::vector<ParamRange> ModelSpec::bounds() const {
  std::vector<ParamRange> out;
  for (int c = 0; c < 3; ++c)
    for (const auto& p : channel_params) out.push_back(p.fit);
  for (const auto& p : shared_params) out.push_back(p.fit);
  return out;
}

std::vector<ParamRange> ModelSpec::domain() const {
  std::vector<ParamRange> out;
  for (int c = 0; c < 3; ++c)
    for (const auto& p : channel_params) out.push_back(p.domain);
  for (const auto& p : shared_params) out.push_back(p.domain);
  return out;
}

}  // namespace fl::fresnel
