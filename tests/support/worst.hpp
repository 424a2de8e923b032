// The worst error of each named measure within one test case, printed when it ends: the tests
// that compare against a reference keep it (worst("title")("what", err) returns err).
#pragma once

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <utility>

namespace ctga::test {

struct worst {
    std::string title;
    std::map<std::string, double> seen;
    explicit worst(std::string t) : title(std::move(t)) {}
    double operator()(const std::string& what, double err) {
        double& w = seen[what];
        w = std::max(w, err);
        return err;
    }
    ~worst() {
        std::printf("%s: worst errors\n", title.c_str());
        for (const auto& [what, err] : seen) std::printf("  %-58s %.3e\n", what.c_str(), err);
    }
    worst(const worst&) = delete;
    worst& operator=(const worst&) = delete;
};

}  // namespace ctga::test
