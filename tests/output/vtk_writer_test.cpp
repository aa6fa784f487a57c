/// @file
/// write_solution_vtu and write_pvd, read back with VTK's own readers: sizes, cell types, field
/// names, and a linear function reproduced to round-off at every sample point.

#include "output/vtk_writer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <Eigen/LU>
#include <filesystem>
#include <map>
#include <stdexcept>

#include "spaces/extracted_evaluator.hpp"
#include "spaces/g1/bernstein_face.hpp"

namespace iga {
namespace {

namespace fs = std::filesystem;

/// An element of the test space: affine map x = origin + J (xi, eta) and the global indices of its
/// local Lagrange functions (Q1: corners (0,0), (1,0), (0,1), (1,1); P1: vertices (0,0), (1,0), (0,1)).
struct AffineElement {
  CellShape shape;
  Point2 origin;
  Eigen::Matrix2d J;
  std::vector<int> dofs;
};

/// Test-only space of continuous Q1 / P1 Lagrange functions on affine elements, built the way a
/// space is (spaces/element_core.hpp): a local basis (the degree-1 Bernstein basis, whose local
/// order is the corner order above), C_e = I and the affine map, evaluated by the generic
/// evaluator. It fills only the arrays it is asked for, so a writer that forgets update_hessians
/// would read empty arrays.
class AffineLagrangeSpace : public Space {
 public:
  AffineLagrangeSpace(std::vector<AffineElement> elements, std::vector<Point2> nodes)
      : elements_(std::move(elements)), nodes_(std::move(nodes)) {
    SpaceFacts facts;
    facts.type = "affine-lagrange-test";
    facts.dimension = static_cast<int>(nodes_.size());
    facts.num_elements = static_cast<int>(elements_.size());
    for (const AffineElement& e : elements_) facts.cell_shapes.push_back(e.shape);
    facts.degree = 1;
    facts.affine_elements = true;
    set_facts(std::move(facts));
    for (CellShape shape : {CellShape::quadrilateral, CellShape::triangle}) {
      const int n = bernstein_count(shape, 1);
      identity_[static_cast<int>(shape)].resize(n, n);
      identity_[static_cast<int>(shape)].setIdentity();
    }
  }

  /// 2 x 2 grid of parameter-space unit squares [i,i+1] x [j,j+1], mapped by x = A s + b;
  /// node (a, b) of the 3 x 3 grid is global function 3 b + a.
  static AffineLagrangeSpace q1_grid(const Eigen::Matrix2d& A, const Point2& b) {
    std::vector<AffineElement> elements;
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        elements.push_back({CellShape::quadrilateral, A * Point2(i, j) + b, A,
                            {3 * j + i, 3 * j + i + 1, 3 * (j + 1) + i, 3 * (j + 1) + i + 1}});
    std::vector<Point2> nodes;
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) nodes.push_back(A * Point2(i, j) + b);
    return AffineLagrangeSpace(std::move(elements), std::move(nodes));
  }

  /// The square [0,1]^2 cut along (1,0)-(0,1) into two P1 triangles.
  static AffineLagrangeSpace p1_square() {
    const std::vector<Point2> v = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    auto triangle = [&](int a, int b, int c) {
      Eigen::Matrix2d J;
      J << v[b] - v[a], v[c] - v[a];
      return AffineElement{CellShape::triangle, v[a], J, {a, b, c}};
    };
    return AffineLagrangeSpace({triangle(0, 1, 3), triangle(2, 3, 1)}, v);
  }

  /// Coefficients interpolating f at the nodes (exact for f linear).
  Eigen::VectorXd interpolate(const std::function<double(const Point2&)>& f) const {
    Eigen::VectorXd c(dimension());
    for (int i = 0; i < dimension(); ++i) c(i) = f(nodes_[i]);
    return c;
  }

  struct Core {
    using Jet = GeometryJet;
    static constexpr bool identity = false;  // planar cores state their extraction: here I
    const AffineLagrangeSpace& space;

    int kind(int e) const { return static_cast<int>(space.elements_.at(e).shape); }
    int tabulate(int kind, const std::vector<Point2>& points, int /*order*/, LocalTables& t) const {
      bernstein_tables(static_cast<CellShape>(kind), 1, points, t);
      return 2;
    }
    const std::vector<int>& active(int e) const { return space.elements_.at(e).dofs; }
    Extraction extraction(int e) const { return extraction_view(space.identity_[kind(e)]); }
    void map(int e, const QuadratureRule& rule, const LocalTables& /*t*/, int /*order*/, std::vector<Jet>& jets) const {
      const AffineElement& el = space.elements_.at(e);
      jets.resize(rule.size());
      for (int k = 0; k < rule.size(); ++k) {
        jets[k].x = el.origin + el.J * rule.points[k];
        jets[k].jacobian = el.J;
      }
    }
  };

  std::unique_ptr<Evaluator> make_evaluator() const override {
    return std::make_unique<ExtractedEvaluator<Core>>(*this, Core{*this});
  }
  void element_dofs(int element, std::vector<int>& out) const override { out = elements_.at(element).dofs; }
  // The writer never integrates: these two throw so a test would notice if it started to.
  RulePtr quadrature(int, int) const override { throw std::logic_error("quadrature not used by the writer"); }
  RulePtr edge_quadrature(int, int, int) const override { throw std::logic_error("edge_quadrature not used"); }

 private:
  std::vector<AffineElement> elements_;
  std::vector<Point2> nodes_;
  Eigen::SparseMatrix<double> identity_[2];  // C_e of a quadrilateral (4 x 4) and a triangle (3 x 3)
};

double linear(const Point2& p) { return 1 + 2 * p.x() + 3 * p.y(); }

/// A fresh directory per test, removed afterwards.
class VtkWriterTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("iga_vtk_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  static vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const std::string& file) {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(file.c_str());
    reader->Update();
    return reader->GetOutput();
  }

  fs::path dir_;
};

TEST_F(VtkWriterTest, FurtherFunctionsBecomePointFieldsOfTheirValues) {
  // The eigenmodes of an eigenproblem are written this way (mode_1, mode_2, ...), beside u.
  const auto space = AffineLagrangeSpace::q1_grid(Eigen::Matrix2d::Identity(), Point2(0, 0));
  VtkFieldOptions options;
  const auto other = [](const Point2& p) { return 2 - p.x() + 5 * p.y(); };
  options.point_functions.emplace_back("mode_2", space.interpolate(other));
  const std::string file = path("modes.vtu");
  write_solution_vtu(space, space.interpolate(linear), options, file);
  const auto grid = read_vtu(file);
  vtkDataArray* u = grid->GetPointData()->GetArray("u");
  vtkDataArray* mode = grid->GetPointData()->GetArray("mode_2");
  ASSERT_NE(mode, nullptr);
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
    const double* x = grid->GetPoint(i);
    EXPECT_NEAR(mode->GetComponent(i, 0), other(Point2(x[0], x[1])), 1e-5);  // float32 fields
    EXPECT_NEAR(u->GetComponent(i, 0), linear(Point2(x[0], x[1])), 1e-5);
  }
  options.point_functions.front().second.resize(3);
  EXPECT_THROW(write_solution_vtu(space, space.interpolate(linear), options, file), std::invalid_argument);
}

TEST_F(VtkWriterTest, Q1GridReproducesLinearFunctionWithAllFields) {
  Eigen::Matrix2d A;
  A << 1.0, 0.25, 0.0, 1.5;  // sheared, stretched: physical and reference gradients differ
  const auto space = AffineLagrangeSpace::q1_grid(A, Point2(0.1, -0.2));
  VtkFieldOptions options;
  options.samples = 4;
  options.exact.u = linear;
  options.laplacian = true;
  const std::string file = path("q1.vtu");
  EXPECT_TRUE(write_solution_vtu(space, space.interpolate(linear), options, file));

  const auto grid = read_vtu(file);
  // 4 bilinear elements: one Lagrange quadrilateral of order 1 each, on the 3 x 3 shared nodes.
  ASSERT_EQ(grid->GetNumberOfPoints(), 9);
  ASSERT_EQ(grid->GetNumberOfCells(), 4);
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) EXPECT_EQ(grid->GetCellType(c), VTK_LAGRANGE_QUADRILATERAL);

  vtkPointData* pd = grid->GetPointData();
  vtkDataArray* u = pd->GetArray("u");
  vtkDataArray* grad = pd->GetArray("grad_u");
  vtkDataArray* exact = pd->GetArray("u_exact");
  vtkDataArray* error = pd->GetArray("error");
  vtkDataArray* laplace = pd->GetArray("laplace_u");
  ASSERT_NE(u, nullptr);
  ASSERT_NE(grad, nullptr);
  ASSERT_NE(exact, nullptr);
  ASSERT_NE(error, nullptr);
  ASSERT_NE(laplace, nullptr);
  EXPECT_EQ(u->GetNumberOfComponents(), 1);
  EXPECT_EQ(grad->GetNumberOfComponents(), 3);

  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  // Fields are stored in single precision: relative 2^-24 of values of order 10.
  const double single = 1e-6 * 10;
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p) {
    double x[3];
    grid->GetPoint(p, x);
    EXPECT_EQ(x[2], 0.0);
    const double expected = linear(Point2(x[0], x[1]));
    EXPECT_NEAR(u->GetComponent(p, 0), expected, single) << "point " << p;
    EXPECT_NEAR(grad->GetComponent(p, 0), 2.0, single) << "point " << p;
    EXPECT_NEAR(grad->GetComponent(p, 1), 3.0, single) << "point " << p;
    EXPECT_EQ(grad->GetComponent(p, 2), 0.0);
    EXPECT_NEAR(exact->GetComponent(p, 0), expected, single);
    // The error is computed in double precision and stored itself: round-off, not float resolution.
    EXPECT_NEAR(error->GetComponent(p, 0), 0.0, 1e-12);
    // Each bilinear function has a nonzero physical Laplacian under this shear; their sum must not.
    EXPECT_NEAR(laplace->GetComponent(p, 0), 0.0, 1e-12);
    for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], x[d]), hi[d] = std::max(hi[d], x[d]);
  }
  // The image of [0,2]^2 under x = A s + b (single-precision coordinates).
  EXPECT_NEAR(lo[0], 0.1, 1e-6);
  EXPECT_NEAR(hi[0], 2.6, 1e-6);
  EXPECT_NEAR(lo[1], -0.2, 1e-6);
  EXPECT_NEAR(hi[1], 2.8, 1e-6);

  vtkDataArray* element = grid->GetCellData()->GetArray("element");
  ASSERT_NE(element, nullptr);
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) EXPECT_EQ(element->GetComponent(c, 0), c);
  // The interpolant is exact: every element's sampled error vanishes.
  vtkDataArray* error_l2 = grid->GetCellData()->GetArray("error_l2");
  ASSERT_NE(error_l2, nullptr);
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) EXPECT_LT(error_l2->GetComponent(c, 0), 1e-12);
  // Without the exact gradient there is no error_h1.
  EXPECT_EQ(grid->GetCellData()->GetArray("error_h1"), nullptr);
}

TEST_F(VtkWriterTest, ExactDataComeFromTheBatchWhenGiven) {
  // With the batch (u and its derivatives as one program, as the solver passes them), the
  // exact-solution fields and the element errors come from it: here a batch for u + 1 and its
  // derivatives, so u_exact is u + 1, the error −1 and error_h1 zero.
  const auto space = AffineLagrangeSpace::q1_grid(Eigen::Matrix2d::Identity(), Point2(0, 0));
  VtkFieldOptions options;
  options.exact.u = linear;
  options.exact.ux = [](const Point2&) { return 2.0; };
  options.exact.uy = [](const Point2&) { return 3.0; };
  options.exact.jet = [](const Eigen::Matrix2Xd& x, Eigen::MatrixXd& values) {
    values.setZero(6, x.cols());
    for (Eigen::Index k = 0; k < x.cols(); ++k) values(0, k) = linear(Point2(x.col(k))) + 1.0;
    values.row(1).setConstant(2.0);
    values.row(2).setConstant(3.0);
  };
  const std::string file = path("batch.vtu");
  write_solution_vtu(space, space.interpolate(linear), options, file);
  const auto grid = read_vtu(file);
  // The loops below see every point and cell: 4 Lagrange quadrilaterals of order 1 on 3 x 3 nodes.
  ASSERT_EQ(grid->GetNumberOfPoints(), 9);
  ASSERT_EQ(grid->GetNumberOfCells(), 4);
  vtkDataArray* exact = grid->GetPointData()->GetArray("u_exact");
  vtkDataArray* error = grid->GetPointData()->GetArray("error");
  ASSERT_NE(exact, nullptr);
  ASSERT_NE(error, nullptr);
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p) {
    double x[3];
    grid->GetPoint(p, x);
    EXPECT_NEAR(exact->GetComponent(p, 0), linear(Point2(x[0], x[1])) + 1.0, 1e-5);
    EXPECT_NEAR(error->GetComponent(p, 0), -1.0, 1e-12);
  }
  vtkDataArray* error_h1 = grid->GetCellData()->GetArray("error_h1");
  ASSERT_NE(error_h1, nullptr);
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) EXPECT_LT(error_h1->GetComponent(c, 0), 1e-12);
}

TEST_F(VtkWriterTest, NonlinearCoefficientsMatchHandComputedBilinearValues) {
  // One nonzero coefficient: the hat of the centre node (1,1). On the unit grid its value at a
  // sample point is (1-|x-1|)(1-|y-1|), its gradient the product rule of that.
  const auto space = AffineLagrangeSpace::q1_grid(Eigen::Matrix2d::Identity(), Point2(0, 0));
  Eigen::VectorXd c = Eigen::VectorXd::Zero(9);
  c(4) = 1.0;
  VtkFieldOptions options;
  options.samples = 3;
  options.lagrange = false;  // linear sub-cells: 3 x 3 per element on a shared 7 x 7 grid of points
  const std::string file = path("hat.vtu");
  EXPECT_FALSE(write_solution_vtu(space, c, options, file));
  const auto grid = read_vtu(file);
  ASSERT_EQ(grid->GetNumberOfPoints(), 7 * 7);
  ASSERT_EQ(grid->GetNumberOfCells(), 4 * 9);
  for (vtkIdType cell = 0; cell < grid->GetNumberOfCells(); ++cell) EXPECT_EQ(grid->GetCellType(cell), VTK_QUAD);
  vtkDataArray* u = grid->GetPointData()->GetArray("u");
  vtkDataArray* grad = grid->GetPointData()->GetArray("grad_u");
  // Optional fields are absent when not asked for.
  EXPECT_EQ(grid->GetPointData()->GetArray("u_exact"), nullptr);
  EXPECT_EQ(grid->GetPointData()->GetArray("error"), nullptr);
  EXPECT_EQ(grid->GetPointData()->GetArray("laplace_u"), nullptr);
  int at_peak = 0;
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p) {
    double x[3];
    grid->GetPoint(p, x);
    const double fx = 1 - std::abs(x[0] - 1), fy = 1 - std::abs(x[1] - 1);
    EXPECT_NEAR(u->GetComponent(p, 0), fx * fy, 1e-6);
    // Away from the kinks x = 1, y = 1 the one-sided derivative is unambiguous.
    if (std::abs(x[0] - 1) > 1e-6 && std::abs(x[1] - 1) > 1e-6) {
      EXPECT_NEAR(grad->GetComponent(p, 0), (x[0] < 1 ? 1 : -1) * fy, 1e-6);
      EXPECT_NEAR(grad->GetComponent(p, 1), (x[1] < 1 ? 1 : -1) * fx, 1e-6);
    }
    if (std::abs(u->GetComponent(p, 0) - 1) < 1e-6) ++at_peak;
  }
  EXPECT_EQ(at_peak, 1);  // the centre node, shared by the four elements
}

TEST_F(VtkWriterTest, TrianglesGiveVtkTriangles) {
  const auto space = AffineLagrangeSpace::p1_square();
  VtkFieldOptions options;
  options.samples = 4;
  options.exact.u = linear;
  const std::string file = path("p1.vtu");
  EXPECT_TRUE(write_solution_vtu(space, space.interpolate(linear), options, file));
  const auto grid = read_vtu(file);
  // Two Lagrange triangles of order 1 on the square's four corners.
  ASSERT_EQ(grid->GetNumberOfPoints(), 4);
  ASSERT_EQ(grid->GetNumberOfCells(), 2);
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) EXPECT_EQ(grid->GetCellType(c), VTK_LAGRANGE_TRIANGLE);
  vtkDataArray* u = grid->GetPointData()->GetArray("u");
  vtkDataArray* grad = grid->GetPointData()->GetArray("grad_u");
  vtkDataArray* error = grid->GetPointData()->GetArray("error");
  ASSERT_NE(error, nullptr);
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p) {
    double x[3];
    grid->GetPoint(p, x);
    EXPECT_NEAR(u->GetComponent(p, 0), linear(Point2(x[0], x[1])), 1e-5);
    EXPECT_NEAR(grad->GetComponent(p, 0), 2.0, 1e-6);
    EXPECT_NEAR(grad->GetComponent(p, 1), 3.0, 1e-6);
    EXPECT_NEAR(error->GetComponent(p, 0), 0.0, 1e-12);
  }
}

TEST_F(VtkWriterTest, RejectsWrongCoefficientCountAndUnwritablePath) {
  const auto space = AffineLagrangeSpace::p1_square();
  EXPECT_THROW(write_solution_vtu(space, Eigen::VectorXd::Zero(3), {}, path("bad.vtu")), std::invalid_argument);
  EXPECT_FALSE(fs::exists(path("bad.vtu")));
  testing::internal::CaptureStderr();
  EXPECT_THROW(write_solution_vtu(space, Eigen::VectorXd::Zero(4), {}, path("missing/dir/p1.vtu")),
               std::runtime_error);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");  // the exception is the only report
}

TEST_F(VtkWriterTest, PvdListsDatasetsInOrder) {
  const std::vector<std::string> datasets = {"level0.vtu", "level1.vtu", "sub dir/level2 & <x>.vtu"};
  const std::string file = path("study.pvd");
  write_pvd(datasets, file);

  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(file.c_str());
  ASSERT_EQ(parser->Parse(), 1);
  vtkXMLDataElement* root = parser->GetRootElement();
  ASSERT_NE(root, nullptr);
  EXPECT_STREQ(root->GetName(), "VTKFile");
  EXPECT_STREQ(root->GetAttribute("type"), "Collection");
  EXPECT_STREQ(root->GetAttribute("version"), "0.1");
  ASSERT_EQ(root->GetNumberOfNestedElements(), 1);
  vtkXMLDataElement* collection = root->GetNestedElement(0);
  EXPECT_STREQ(collection->GetName(), "Collection");
  ASSERT_EQ(collection->GetNumberOfNestedElements(), 3);
  for (int i = 0; i < 3; ++i) {
    vtkXMLDataElement* ds = collection->GetNestedElement(i);
    EXPECT_STREQ(ds->GetName(), "DataSet");
    int timestep = -1, part = -1;
    ASSERT_TRUE(ds->GetScalarAttribute("timestep", timestep));
    ASSERT_TRUE(ds->GetScalarAttribute("part", part));
    EXPECT_EQ(timestep, i);
    EXPECT_EQ(part, 0);
    // Special characters survive the round trip (the writer escapes, the parser unescapes).
    EXPECT_EQ(std::string(ds->GetAttribute("file")), datasets[i]);
  }

  EXPECT_THROW(write_pvd(datasets, path("missing/dir/study.pvd")), std::runtime_error);
}

}  // namespace
}  // namespace iga
