// The include structure of analysis/ against its layers (docs/architecture.md, "The layers of
// analysis/"): every #include "folder/..." of a file under analysis/<folder>/ that names a file of
// analysis/ is an arrow between two folders, and none may point into a higher layer: above all,
// none from below the pipeline up into pipeline/ or cli/.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace sbpack {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = SBPACK_SOURCE_DIR;

/// The layers, from the top (0) down: each folder's layer.
using Layers = std::map<std::string, int>;

/// The block under the heading "### The layers of analysis/": lines "name: folder folder ...",
/// the highest layer first. std::runtime_error when the heading or its block is missing.
Layers readLayers(const fs::path& architecture) {
    std::ifstream in(architecture);
    std::string line;
    while (std::getline(in, line) && line != "### The layers of analysis/") {
    }
    while (std::getline(in, line) && line.rfind("```", 0) != 0) {
    }
    Layers layers;
    int layer = 0;
    while (std::getline(in, line) && line.rfind("```", 0) != 0) {
        const std::size_t colon = line.find(':');
        if (colon == std::string::npos) throw std::runtime_error("no 'name:' in '" + line + "'");
        std::istringstream folders(line.substr(colon + 1));
        for (std::string folder; folders >> folder;)
            layers[folder] = layer;
        ++layer;
    }
    if (layers.empty()) throw std::runtime_error("no layers in " + architecture.string());
    return layers;
}

/// One include of a file of analysis/ from another folder's file.
struct Arrow {
    std::string from, to;
    std::string where; ///< the including file and the included path
};

/// The folder of analysis/ a file lies in (its first component below analysis/).
std::string folderOf(const fs::path& file, const fs::path& analysis) {
    return fs::relative(file, analysis).begin()->string();
}

/// Every include "folder/..." in the sources of analysis/*/ that names a file of analysis/ (not
/// one of common/, whose folders cli/, contacts/ and order/ share their names), between folders.
std::vector<Arrow> includeArrows(const fs::path& analysis) {
    static const std::regex include(R"(^\s*#\s*include\s*"(([a-z_]+)/[^"]+)\")");
    std::vector<Arrow> arrows;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(analysis)) {
        const std::string extension = entry.path().extension().string();
        if (!entry.is_regular_file() || entry.path().parent_path() == analysis ||
            (extension != ".hpp" && extension != ".cpp" && extension != ".cu"))
            continue;
        const std::string from = folderOf(entry.path(), analysis);
        std::ifstream in(entry.path());
        std::smatch match;
        for (std::string line; std::getline(in, line);)
            if (std::regex_search(line, match, include) && match[2] != from &&
                fs::exists(analysis / match[1].str()))
                arrows.push_back({from, match[2],
                                  fs::relative(entry.path(), analysis.parent_path()).string() +
                                      ": " + match[1].str()});
    }
    return arrows;
}

/// The arrows into a higher layer, each as "file: included (from-layer folder up to to's)".
std::vector<std::string> upwardArrows(const Layers& layers, const std::vector<Arrow>& arrows) {
    std::vector<std::string> up;
    for (const Arrow& a : arrows)
        if (layers.at(a.to) < layers.at(a.from))
            up.push_back(a.where + " (" + a.from + "/ includes " + a.to + "/, a higher layer)");
    return up;
}

Layers documentedLayers() {
    return readLayers(kSource / "docs" / "architecture.md");
}

TEST(IncludeLayers, EveryFolderHasOneLayer) {
    const Layers layers = documentedLayers();
    std::set<std::string> folders;
    for (const fs::directory_entry& entry : fs::directory_iterator(kSource / "analysis"))
        if (entry.is_directory()) folders.insert(entry.path().filename().string());
    for (const std::string& folder : folders)
        EXPECT_TRUE(layers.contains(folder)) << "analysis/" << folder << "/ has no layer";
    for (const auto& [folder, layer] : layers)
        EXPECT_TRUE(folders.contains(folder)) << "layer of a missing folder: " << folder;
    EXPECT_LT(layers.at("gpu"), layers.at("grid")); // the back end above the shared arithmetic
    EXPECT_LT(layers.at("pipeline"), layers.at("gpu"));
}

TEST(IncludeLayers, NoIncludePointsUp) {
    const std::vector<Arrow> arrows = includeArrows(kSource / "analysis");
    ASSERT_GT(arrows.size(), 100u); // the sources were found
    for (const std::string& up : upwardArrows(documentedLayers(), arrows))
        ADD_FAILURE() << up;
}

TEST(IncludeLayers, AnArrowUpIntoThePipelineIsFound) {
    const Layers layers{{"cli", 0}, {"pipeline", 1}, {"gpu", 2}, {"grid", 3}};
    const std::vector<Arrow> arrows{{"gpu", "pipeline", "gpu/x.cpp: pipeline/stage.hpp"},
                                    {"pipeline", "gpu", "pipeline/y.cpp: gpu/z.hpp"},
                                    {"grid", "cli", "grid/w.hpp: cli/v.hpp"}};
    const std::vector<std::string> up = upwardArrows(layers, arrows);
    ASSERT_EQ(up.size(), 2u);
    EXPECT_NE(up[0].find("gpu/ includes pipeline/"), std::string::npos) << up[0];
    EXPECT_NE(up[1].find("grid/ includes cli/"), std::string::npos) << up[1];
}

} // namespace
} // namespace sbpack
