/// @file
/// Shape classes of a WS4 mesh: elements that are translates of each other (with equal frames,
/// edge orientations and scales) share one extraction and one double-double element matrix. The
/// shared ones must be what each element would get on its own, to round-off.

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>

#include "spaces/closed_forms.hpp"
#include "spaces/ws4/ws4_hermite_transform.hpp"
#include "spaces/ws4/ws4_reference_matrices.hpp"
#include "spaces/ws4/ws4_space.hpp"

namespace iga::ws4 {
namespace {

/// Largest column-wise relative difference of two extractions (columns are shape functions).
double column_difference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  double worst = 0.0;
  for (int m = 0; m < a.cols(); ++m)
    worst = std::max(worst, (a.col(m) - b.col(m)).cwiseAbs().maxCoeff() / b.col(m).cwiseAbs().maxCoeff());
  return worst;
}

TEST(Ws4ShapeClasses, AStructuredMeshHasFewClassesAndEachElementGetsItsOwnExtraction) {
  // A dyadic grid (differences exact) and one whose corner differences round differently.
  for (const auto& [low, high] : {std::pair{Point2(0, 0), Point2(1, 1)}, std::pair{Point2(0.1, -0.3), Point2(1.4, 0.7)}}) {
    const Ws4Space space(Triangulation::rectangle(8, 8, low, high));
    const ShapeClasses& classes = space.shape_classes();
    std::cout << space.num_elements() << " elements, " << classes.size() << " shape classes\n";
    // Interior elements differ only by translation: a few classes per orientation and boundary.
    EXPECT_LT(classes.size(), space.num_elements() / 2);
    double worst = 0.0;
    for (int t = 0; t < space.num_elements(); ++t) {
      const int rep = classes.representative[classes.of_element[t]];
      EXPECT_EQ(space.jacobian(t), space.jacobian(rep)) << t;
      // Its own extraction, from its untranslated corners.
      worst = std::max(worst, column_difference(space.extraction(t), ws4_exact_extraction(space.dof_geometry(t))));
    }
    std::cout << "shared vs own extraction, worst relative column difference " << worst << "\n";
    EXPECT_LT(worst, 1e-12);
  }
}

TEST(Ws4ShapeClasses, CachedDoubleDoubleElementMatricesAreTheElementsOwn) {
  const Ws4Space space(Triangulation::rectangle(6, 6, Point2(0, 0), Point2(1, 1)));
  for (BilinearForm form : {BilinearForm::laplace, BilinearForm::bilaplace}) {
    double worst = 0.0;
    for (int t = 0; t < space.num_elements(); ++t) {
      DoubleDoubleMatrix cached, own;
      ASSERT_TRUE(space.closed_forms()->element_matrix(t, form, cached));
      affine_element_matrix(form, space.jacobian(t), ws4_reference_integrals_double_double(form),
                            ws4_exact_extraction(space.dof_geometry(t)), own);
      const double scale = own.hi.cwiseAbs().maxCoeff();
      for (int j = 0; j < 51; ++j)
        for (int i = 0; i < 51; ++i)
          worst = std::max(worst, std::abs((cached(i, j) - own(i, j)).hi) / scale);
      // Every element of a class gets exactly the matrix of the class.
      const int rep = space.shape_classes().representative[space.shape_classes().of_element[t]];
      DoubleDoubleMatrix of_rep;
      affine_element_matrix(form, space.jacobian(rep), ws4_reference_integrals_double_double(form), space.extraction(rep),
                            of_rep);
      EXPECT_EQ(cached.hi, of_rep.hi) << t;
      EXPECT_EQ(cached.lo, of_rep.lo) << t;
    }
    std::cout << "form " << static_cast<int>(form) << ": cached vs own element matrix, worst relative " << worst << "\n";
    // The extractions differ by round-off of the corner translation only.
    EXPECT_LT(worst, 1e-12);
  }
}

TEST(Ws4ShapeClasses, PreparedSharedMatricesAreTheClosedFormsOfEveryElement) {
  const Ws4Space space(Triangulation::rectangle(12, 12, Point2(0, 0), Point2(1, 1)));
  const ShapeClasses& classes = space.shape_classes();
  for (BilinearForm form : {BilinearForm::mass, BilinearForm::bilaplace}) {
    EXPECT_EQ(space.closed_forms()->shared<DoubleDoubleMatrix>(0, form), nullptr) << "nothing is shared before preparing";
    space.closed_forms()->prepare<DoubleDoubleMatrix>(form);
    int shared = 0;
    for (int t = 0; t < space.num_elements(); ++t) {
      const DoubleDoubleMatrix* m = space.closed_forms()->shared<DoubleDoubleMatrix>(t, form);
      // Classes of one element keep no matrix; all others share the class's.
      ASSERT_EQ(m != nullptr, classes.count[classes.of_element[t]] > 1) << t;
      if (!m) continue;
      ++shared;
      DoubleDoubleMatrix own;
      ASSERT_TRUE(space.closed_forms()->element_matrix(t, form, own));
      EXPECT_EQ(m->hi, own.hi) << t;
      EXPECT_EQ(m->lo, own.lo) << t;
    }
    std::cout << shared << " of " << space.num_elements() << " elements share a matrix\n";
    EXPECT_GT(shared, space.num_elements() / 2);
  }
}

}  // namespace
}  // namespace iga::ws4
