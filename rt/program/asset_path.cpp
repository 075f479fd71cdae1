#include "rt/program/asset_path.h"

namespace rt {

std::string asset_path(const std::string& name) {
    return std::string(RT_ASSET_DIR) + "/" + name;
}

}  // namespace rt
