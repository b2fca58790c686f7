// Whether a LIGGGHTS input uses a variable (the coarse-graining refusal's
// ${cg} check): the scripts' own text, includes followed, comments not.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "LiggghtsInputCheck.H"

namespace
{

namespace fs = std::filesystem;

// A main input that includes 'included', both written to a fresh directory.
std::string inputs(const std::string& name, const std::string& main, const std::string& included)
{
    const fs::path dir = fs::temp_directory_path()/("spoutlab_inputcheck_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir/"in.main") << "variable inputDir index " << dir.string() << "\n" << main;
    std::ofstream(dir/"in.part") << included;
    return (dir/"in.main").string();
}

bool usesCg(const std::string& name, const std::string& main, const std::string& included = "")
{
    return spoutlab::usesVariable(inputs(name, main, included), {}, "cg");
}

} // namespace

TEST(LiggghtsInputCheck, CgInTheInputOrAnIncludeIsUsed)
{
    EXPECT_TRUE(usesCg("own", "variable d equal ${cg}*${dp}\n"));
    EXPECT_TRUE(usesCg("equal", "variable d equal v_cg*0.008\n"));
    EXPECT_TRUE(usesCg("include", "include ${inputDir}/in.part\n", "variable k equal ${cg}*800\n"));
    EXPECT_TRUE(usesCg("continued", "variable d equal &\n    ${cg}*0.008\n"));
}

TEST(LiggghtsInputCheck, OtherNamesCommentsAndUnfollowedIncludesAreNot)
{
    EXPECT_FALSE(usesCg("none", "variable d equal 0.008\n"));
    EXPECT_FALSE(usesCg("longer", "variable d equal ${cgBed}*v_cgBed\n"));
    EXPECT_FALSE(usesCg("prefix", "variable d equal v_dcg*0.008\n"));
    EXPECT_FALSE(usesCg("comment", "variable d equal 0.008   # not ${cg}\n"));
    EXPECT_FALSE(usesCg("notIncluded", "variable x index 1\n", "variable k equal ${cg}*800\n"));
}
