#include "device_choice.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "errors.hpp"

namespace pxflow {
namespace {

// More digits than this can never be an index (and would overflow the parse).
constexpr std::size_t kMaxIndexDigits = 9;

std::string lowercase(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool all_digits(std::string_view s) {
  return std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
}

std::string describe_devices(const std::vector<DeviceLabel>& devices) {
  std::string text;
  for (std::size_t i = 0; i < devices.size(); ++i)
    text += (i ? ", " : "") + std::to_string(i) + " '" + devices[i].name + "' (" +
            devices[i].detail + ")";
  return text.empty() ? "none" : text;
}

}  // namespace

std::size_t device_index_for(std::string_view family, const std::vector<DeviceLabel>& devices,
                             std::string_view request) {
  if (request.empty())
    throw std::logic_error("device_index_for: an empty request is the family's default");
  const std::string known = " (devices: " + describe_devices(devices) + ")";
  const std::string who(family);
  if (all_digits(request)) {
    const std::size_t index = request.size() > kMaxIndexDigits
                                  ? devices.size()
                                  : static_cast<std::size_t>(std::stoul(std::string(request)));
    if (index >= devices.size())
      throw InputError(who + ": device index " + std::string(request) + " is out of range" + known);
    return index;
  }
  const std::string wanted = lowercase(request);
  for (std::size_t i = 0; i < devices.size(); ++i)
    if (lowercase(devices[i].name).find(wanted) != std::string::npos) return i;
  throw InputError(who + ": no device name contains '" + std::string(request) + "'" + known);
}

}  // namespace pxflow
