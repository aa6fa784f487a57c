// The MPI writer of a distributed run's VTK dataset (parallel_vtk.hpp), part of the PETSc plugin:
// VTK's MPI controller loads MPI, which a serial run must not.
#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkMPIController.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPUnstructuredGridWriter.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "output/parallel_vtk_pieces.hpp"
#include "output/vtk_writer.hpp"
#include "solver/petsc_session.hpp"
#include "solver/rank_part.hpp"
#include "spaces/space_part.hpp"

namespace iga {

namespace fs = std::filesystem;

namespace {

/// Some elements of a space, renumbered 0 .. n-1, for drawing them alone: every query about
/// element e is asked of the space's element elements[e]. The functions keep their global numbers
/// (coefficients are the whole space's).
class ElementSubsetView final : public Space {
 public:
  ElementSubsetView(const Space& space, std::vector<int> elements) : space_(space), elements_(std::move(elements)) {
    SpaceFacts facts = space.facts();
    facts.num_elements = static_cast<int>(elements_.size());
    facts.cell_shapes.clear();
    for (int e : elements_) facts.cell_shapes.push_back(space.cell_shape(e));
    // Not needed for drawing (and the edges' element numbers would be the space's).
    for (auto& part : facts.boundary_parts) part.second.clear();
    facts.all_boundary_edges.clear();
    set_facts(std::move(facts));
  }

  class SubsetEvaluator final : public Evaluator {
   public:
    SubsetEvaluator(const Space& view, std::unique_ptr<Evaluator> inner, const std::vector<int>& elements)
        : Evaluator(view), inner_(std::move(inner)), elements_(elements) {}
    void evaluate(int e, const QuadratureRule& points, unsigned flags, PointValues& out) override {
      inner_->evaluate(elements_[e], points, flags, out);
    }
    void evaluate_element_function(int e, const QuadratureRule& points, const Eigen::VectorXd& element_coefficients,
                                   unsigned flags, PointValues& geometry, FunctionValues& out) override {
      inner_->evaluate_element_function(elements_[e], points, element_coefficients, flags, geometry, out);
    }
    void evaluate_geometry(int e, const QuadratureRule& points, PointValues& out) override {
      inner_->evaluate_geometry(elements_[e], points, out);
    }
    void integrate_values(int e, const QuadratureRule& points, const PointValues& geometry,
                          const Eigen::VectorXd& weights, Eigen::VectorXd& local) override {
      inner_->integrate_values(elements_[e], points, geometry, weights, local);
    }

   private:
    std::unique_ptr<Evaluator> inner_;
    const std::vector<int>& elements_;
  };

  std::unique_ptr<Evaluator> make_evaluator() const override {
    return std::make_unique<SubsetEvaluator>(*this, space_.make_evaluator(), elements_);
  }
  void element_dofs(int e, std::vector<int>& out) const override { space_.element_dofs(elements_[e], out); }
  RulePtr quadrature(int e, int degree) const override { return space_.quadrature(elements_[e], degree); }
  RulePtr edge_quadrature(int e, int edge, int degree) const override {
    return space_.edge_quadrature(elements_[e], edge, degree);
  }

 private:
  const Space& space_;
  std::vector<int> elements_;
};

/// VTK's MPI controller on the world communicator PETSc runs on, initialised once (MPI itself was
/// initialised by PETSc). Released just before PETSc finalises MPI: Finalize(1) frees the
/// communicators VTK duplicated without finalising MPI, which stays PETSc's.
vtkMPIController* vtk_controller() {
  static vtkMPIController* controller = [] {
    vtkMPIController* c = vtkMPIController::New();
    c->Initialize(nullptr, nullptr, 1);
    before_mpi_finalize([c] {
      c->Finalize(1);
      c->Delete();
    });
    return c;
  }();
  return controller;
}

}  // namespace

bool write_solution_pvtu_mpi(const Space& space, const Eigen::VectorXd& coefficients, const VtkFieldOptions& options,
                         const std::string& pvtu_filename) {
  const int rank = mpi_rank(), ranks = mpi_size();
  const fs::path pvtu(pvtu_filename);
  bool lagrange = false;
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  // Local work: this rank's elements drawn by the serial writer (into a scratch file beside the
  // pieces), read back and given their global element numbers.
  on_every_rank([&] {
    // A rank's part of the space draws its own elements; a whole space the partition's share.
    const auto* part = dynamic_cast<const SpacePart*>(&space);
    std::vector<int> mine;
    if (part) {
      mine = part->owned_elements();
    } else {
      mine = rank_elements(space, rank, ranks);
    }
    if (mine.empty()) return;  // more ranks than elements: no piece
    VtkFieldOptions own = options;
    for (auto& [name, values] : own.element_fields) {
      std::vector<double> subset;
      subset.reserve(mine.size());
      for (int e : mine) subset.push_back(values.at(e));
      values = std::move(subset);
    }
    const fs::path scratch = pvtu.parent_path() / ("." + pvtu.stem().string() + "_" + std::to_string(rank) + ".partial.vtu");
    const ElementSubsetView view(space, mine);
    lagrange = write_solution_vtu(view, coefficients, own, scratch.string());
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(scratch.c_str());
    reader->Update();
    std::error_code ec;
    fs::remove(scratch, ec);
    grid->ShallowCopy(reader->GetOutput());
    auto* element = vtkIntArray::SafeDownCast(grid->GetCellData()->GetArray("element"));
    if (!element || grid->GetNumberOfCells() == 0)
      throw std::runtime_error("cannot read back the VTK piece of rank " + std::to_string(rank));
    for (vtkIdType c = 0; c < element->GetNumberOfTuples(); ++c) {
      const int e = mine.at(element->GetValue(c));
      element->SetValue(c, part ? part->elements()[e] : e);
    }
  });
  // Collective inside VTK: the writer reduces which pieces were written, rank 0 lists them.
  vtkNew<vtkXMLPUnstructuredGridWriter> writer;
  writer->SetController(vtk_controller());
  writer->SetInputData(grid);
  writer->SetFileName(pvtu.c_str());
  writer->SetNumberOfPieces(ranks);
  writer->SetStartPiece(rank);
  writer->SetEndPiece(rank);
  writer->SetWriteSummaryFile(1);  // on every rank: the reduction is collective; the controller lets rank 0 write
  writer->SetDataModeToAppended();
  set_vtk_compression(*writer, options.compression);
  const int ok = writer->Write();
  on_every_rank([&] {
    if (!ok || writer->GetErrorCode() != 0)
      throw std::runtime_error("cannot write the VTK piece '" + piece_path(pvtu, rank).string() + "' or '" +
                               pvtu.string() + "'");
  });
  return broadcast_from_root(lagrange ? "1" : "0") == "1";
}

}  // namespace iga
