// The run-time selection every model family uses, on a family of its own made
// up here (so the real families' lists stay as they are): models join from a
// static object, names come back sorted whatever the order they joined in, an
// unknown name gets the one-line error against the selecting dictionary, and
// settings reach the model.

#include "InputError.hpp"
#include "ModelFamilies.hpp"
#include "ModelRegistry.hpp"
#include "Parameters.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

using namespace spoutlab;

namespace
{

class Shape
{
public:
    virtual ~Shape() = default;
    virtual double area() const = 0;
    static ModelRegistry<Shape>& registry()
    {
        static ModelRegistry<Shape> shapes("shapeModel");
        return shapes;
    }
};

class Square : public Shape
{
public:
    explicit Square(const Parameters& p) : side_(p.getScalar("side", 1.0)) {}
    double area() const override { return side_ * side_; }

private:
    double side_;
};

class Circle : public Shape
{
public:
    explicit Circle(const Parameters& p) : radius_(p.getScalar("radius", 1.0)) {}
    double area() const override { return 3.0 * radius_ * radius_; }

private:
    double radius_;
};

// joined in reverse alphabetical order, as two separate model files might
const Registration<Shape, Square> square("square");
const Registration<Shape, Circle> circle("circle");

std::string errorOf(const std::string& name, const Parameters& props)
{
    try
    {
        Shape::registry().create(name, props);
    }
    catch (const InputError& e)
    {
        return e.what();
    }
    return "";
}

} // namespace

TEST(ModelRegistry, ModelsJoinFromStaticObjectsAndAreListedSorted)
{
    EXPECT_EQ(Shape::registry().key(), "shapeModel");
    EXPECT_EQ(Shape::registry().names(), (std::vector<std::string>{"circle", "square"}));
    EXPECT_EQ(Shape::registry().namesList(), "circle, square");
}

TEST(ModelRegistry, CreatesTheNamedModelWithItsSettings)
{
    Parameters props("caseDict/squareProps");
    props.set("side", "3");
    EXPECT_DOUBLE_EQ(Shape::registry().create("square", props)->area(), 9.0);
    EXPECT_DOUBLE_EQ(Shape::registry().create("circle", Parameters("x"))->area(), 3.0);
}

TEST(ModelRegistry, UnknownNameIsReportedAgainstTheSelectingDictionary)
{
    // settings in <name>Props: the key that named the model is in the parent
    EXPECT_EQ(errorOf("hexagon", Parameters("constant/caseDict/hexagonProps")),
              "constant/caseDict: key 'shapeModel' expected one of circle, square, got 'hexagon'");
    // settings elsewhere: the error names them as they are
    EXPECT_EQ(errorOf("hexagon", Parameters("inline")),
              "inline: key 'shapeModel' expected one of circle, square, got 'hexagon'");
    EXPECT_EQ(errorOf("hexagon", Parameters("a/squareProps")),
              "a/squareProps: key 'shapeModel' expected one of circle, square, got 'hexagon'");
    // names are matched exactly
    EXPECT_NE(errorOf("Square", Parameters("d/SquareProps")), "");
}

TEST(ModelRegistry, RequireChecksANameWithoutMakingTheModel)
{
    EXPECT_NO_THROW(Shape::registry().require("circle", "caseDict"));
    try
    {
        Shape::registry().require("cube", "caseDict");
        FAIL() << "no InputError";
    }
    catch (const InputError& e)
    {
        EXPECT_STREQ(e.what(), "caseDict: key 'shapeModel' expected one of circle, square, got 'cube'");
    }
}

TEST(ModelRegistry, ANameRegisteredTwiceIsAProgrammingError)
{
    ModelRegistry<Shape> local("shapeModel");
    local.add("square",
              [](const Parameters& p) -> std::unique_ptr<Shape> { return std::make_unique<Square>(p); });
    EXPECT_THROW(
        local.add("square",
                  [](const Parameters& p) -> std::unique_ptr<Shape> { return std::make_unique<Circle>(p); }),
        std::logic_error);
    EXPECT_EQ(local.names(), std::vector<std::string>{"square"});
}

// What spoutFoam -listModels prints: each family once, under the key that
// selects it, with the names its errors list.
TEST(ModelFamilies, EveryFamilyWithItsKeyAndNames)
{
    const auto families = modelFamilies();
    ASSERT_EQ(families.size(), 4u);
    EXPECT_EQ(families[0].key, "dragModel");
    EXPECT_EQ(families[0].names, "Beetstra, DiFelice, Gidaspow");
    EXPECT_EQ(families[1].key, "voidFractionModel");
    EXPECT_EQ(families[1].names, "centre, divided");
    EXPECT_EQ(families[2].key, "heatTransferModel");
    EXPECT_EQ(families[2].names, "Gunn, RanzMarshall, Sartori, spoutDowncomer");
    EXPECT_EQ(families[3].key, "dryingModel");
    EXPECT_EQ(families[3].names, "freeWater, kernelDiffusion, reactionEngineering");
}
