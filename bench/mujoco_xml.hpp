// A MuJoCo model from an MJCF string (mj_loadXML through a virtual file system): the benchmarks
// write their models from the same numbers ctga is given. The error MuJoCo reports goes to error.
#pragma once

#include <cstring>
#include <memory>
#include <string>

#include <mujoco/mujoco.h>

namespace bench {

inline mjModel* load_mjcf(const std::string& xml, const std::string& name, std::string& error) {
    auto vfs = std::make_unique<mjVFS>();
    mj_defaultVFS(vfs.get());
    if (mj_makeEmptyFileVFS(vfs.get(), name.c_str(), static_cast<int>(xml.size())) != 0) {
        error = "mj_makeEmptyFileVFS failed";
        return nullptr;
    }
    const int f = mj_findFileVFS(vfs.get(), name.c_str());
    std::memcpy(vfs->filedata[f], xml.data(), xml.size());
    char buffer[1000] = "";
    mjModel* m = mj_loadXML(name.c_str(), vfs.get(), buffer, sizeof buffer);
    mj_deleteVFS(vfs.get());
    error = buffer;
    return m;
}

}  // namespace bench
