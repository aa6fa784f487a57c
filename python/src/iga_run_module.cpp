// The compiled part of the Python package iga_run (python/iga_run/__init__.py wraps it): studies
// from config text or files, spaces from domain and space settings, evaluation at points.
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <iostream>
#include <limits>
#include <memory>

#include "config/config_node.hpp"
#include "config/errors.hpp"
#include "output/report.hpp"
#include "solver/study.hpp"
#include "spaces/point_location.hpp"
#include "spaces/space_factory.hpp"

namespace py = pybind11;
using namespace iga;

namespace {

using Points = Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor>;

/// A space with its point locator (built on first use: it samples every element).
class PySpace {
 public:
  explicit PySpace(SpacePtr space) : space_(std::move(space)) {}
  const Space& space() const { return *space_; }

  /// Per point the active basis functions (empty outside the domain).
  std::vector<PointBasis> basis(const Points& points) {
    py::gil_scoped_release release;
    if (!locator_) locator_ = std::make_unique<PointLocator>(space_);
    std::vector<std::optional<PointLocation>> where;
    for (Eigen::Index i = 0; i < points.rows(); ++i) where.push_back(locator_->locate(points.row(i).transpose()));
    return locator_->basis_at(where);
  }

 private:
  SpacePtr space_;
  std::unique_ptr<PointLocator> locator_;
};

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

Eigen::MatrixXd basis_values(PySpace& s, const Points& points) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Constant(points.rows(), s.space().dimension(), nan);
  const std::vector<PointBasis> b = s.basis(points);
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    if (b[i].dofs.empty()) continue;
    out.row(i).setZero();
    for (std::size_t k = 0; k < b[i].dofs.size(); ++k) out(i, b[i].dofs[k]) += b[i].value(static_cast<Eigen::Index>(k));
  }
  return out;
}

/// (n, dimension, 2) as a NumPy array.
py::array_t<double> basis_gradients(PySpace& s, const Points& points) {
  const Eigen::Index n = points.rows(), dim = s.space().dimension();
  py::array_t<double> out({n, dim, Eigen::Index{2}});
  auto a = out.mutable_unchecked<3>();
  const std::vector<PointBasis> b = s.basis(points);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < dim; ++j) a(i, j, 0) = a(i, j, 1) = b[i].dofs.empty() ? nan : 0.0;
  for (Eigen::Index i = 0; i < n; ++i)
    for (std::size_t k = 0; k < b[i].dofs.size(); ++k) {
      a(i, b[i].dofs[k], 0) += b[i].dx(static_cast<Eigen::Index>(k));
      a(i, b[i].dofs[k], 1) += b[i].dy(static_cast<Eigen::Index>(k));
    }
  return out;
}

void check_coefficients(const PySpace& s, const Eigen::VectorXd& c) {
  if (c.size() != s.space().dimension())
    throw py::value_error("need one coefficient per basis function: " + std::to_string(s.space().dimension()) + " (got " +
                          std::to_string(c.size()) + ")");
}

/// u_h = Σ c_i N_i at the points (NaN outside the domain).
Eigen::VectorXd evaluate(PySpace& s, const Eigen::VectorXd& c, const Points& points) {
  check_coefficients(s, c);
  Eigen::VectorXd out = Eigen::VectorXd::Constant(points.rows(), nan);
  const std::vector<PointBasis> b = s.basis(points);
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    if (b[i].dofs.empty()) continue;
    double u = 0.0;
    for (std::size_t k = 0; k < b[i].dofs.size(); ++k) u += c(b[i].dofs[k]) * b[i].value(static_cast<Eigen::Index>(k));
    out(i) = u;
  }
  return out;
}

/// ∇u_h at the points, (n, 2) (NaN outside the domain).
Points gradient(PySpace& s, const Eigen::VectorXd& c, const Points& points) {
  check_coefficients(s, c);
  Points out = Points::Constant(points.rows(), 2, nan);
  const std::vector<PointBasis> b = s.basis(points);
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    if (b[i].dofs.empty()) continue;
    out.row(i).setZero();
    for (std::size_t k = 0; k < b[i].dofs.size(); ++k) {
      out(i, 0) += c(b[i].dofs[k]) * b[i].dx(static_cast<Eigen::Index>(k));
      out(i, 1) += c(b[i].dofs[k]) * b[i].dy(static_cast<Eigen::Index>(k));
    }
  }
  return out;
}

/// A study's outcome: summary.json's text, and the finest level's space and coefficients.
struct StudyRun {
  std::string summary;
  std::shared_ptr<PySpace> space;
  Eigen::VectorXd coefficients;
};

StudyRun run(const ConfigNode& root, const std::string& config_path, int levels, bool quiet) {
  py::gil_scoped_release release;
  const StudySettings settings = parse_study(root, config_path, levels, "");
  const ProgressSink progress = [quiet](const std::string& msg) {
    if (!quiet) std::cerr << "iga-run: " << msg << std::endl;
  };
  StudyRun out;
  SpacePtr finest;
  const StudyResult result = run_study(settings, progress, [&](int, const Space& space, const DiscreteSolution& sol) {
    finest = space.shared_from_this();
    out.coefficients = sol.coefficients;
  });
  out.summary = summary_json(settings, result);
  out.space = std::make_shared<PySpace>(finest);
  return out;
}

}  // namespace

PYBIND11_MODULE(_iga_run, m) {
  m.doc() = "iga-run's library: studies, spaces and their evaluation (use the package iga_run)";
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<NumericalError> numerical_error(m, "NumericalError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      input_error(e.what());
    } catch (const NumericalError& e) {
      numerical_error(e.what());
    }
  });
  m.attr("__version__") = IGA_RUN_VERSION;

  py::class_<PySpace, std::shared_ptr<PySpace>>(m, "Space")
      .def_property_readonly("type", [](const PySpace& s) { return s.space().type(); })
      .def_property_readonly("dimension", [](const PySpace& s) { return s.space().dimension(); })
      .def_property_readonly("degree", [](const PySpace& s) { return s.space().degree(); })
      .def_property_readonly("continuity", [](const PySpace& s) { return s.space().continuity(); })
      .def_property_readonly("num_elements", [](const PySpace& s) { return s.space().num_elements(); })
      .def_property_readonly("mesh_size", [](const PySpace& s) { return s.space().mesh_size(); })
      .def_property_readonly("boundary_names", [](const PySpace& s) { return s.space().boundary_names(); })
      .def_property_readonly("parameters",
                             [](const PySpace& s) {
                               py::dict d;
                               for (const auto& [k, v] : s.space().parameters()) d[py::str(k)] = v;
                               return d;
                             })
      .def("basis_values", &basis_values, py::arg("points"))
      .def("basis_gradients", &basis_gradients, py::arg("points"))
      .def("evaluate", &evaluate, py::arg("coefficients"), py::arg("points"))
      .def("gradient", &gradient, py::arg("coefficients"), py::arg("points"));

  py::class_<StudyRun>(m, "StudyRun")
      .def_readonly("summary", &StudyRun::summary)
      .def_readonly("space", &StudyRun::space)
      .def_readonly("coefficients", &StudyRun::coefficients);

  m.def(
      "run_file",
      [](const std::string& path, int levels, bool quiet) { return run(ConfigNode::load_file(path), path, levels, quiet); },
      py::arg("path"), py::arg("levels") = 0, py::arg("quiet") = true);
  m.def(
      "run_text",
      [](const std::string& text, const std::string& name, int levels, bool quiet) {
        return run(ConfigNode::load_string(text, name), name, levels, quiet);
      },
      py::arg("text"), py::arg("name"), py::arg("levels") = 0, py::arg("quiet") = true);
  m.def(
      "make_space",
      [](const std::string& text, const std::string& name, int level) {
        const ConfigNode root = ConfigNode::load_string(text, name);
        root.check_keys({"domain", "space"});
        return std::make_shared<PySpace>(make_space(root["domain"], root["space"], level));
      },
      py::arg("text"), py::arg("name"), py::arg("level") = 0);
}
