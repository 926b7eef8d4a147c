// Geometric multigrid for the bicubic Hermite plate; see the header.
#include <deal.II/base/index_set.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>

#include <nitsche_contact/models/hermite_multigrid.h>

#include <cmath>

namespace NitscheContact
{
  using namespace dealii;

  class HermiteMultigrid::Transfer : public MGTransferBase<VectorType>
  {
  public:
    explicit Transfer(const std::vector<std::unique_ptr<MatrixType>> &p)
      : p(p)
    {}
    void
    prolongate(const unsigned int to_level,
               VectorType        &dst,
               const VectorType  &src) const override
    {
      p[to_level - 1]->vmult(dst, src);
    }
    void
    prolongate_and_add(const unsigned int to_level,
                       VectorType        &dst,
                       const VectorType  &src) const override
    {
      p[to_level - 1]->vmult_add(dst, src);
    }
    void
    restrict_and_add(const unsigned int from_level,
                     VectorType        &dst,
                     const VectorType  &src) const override
    {
      p[from_level - 1]->Tvmult_add(dst, src);
    }

  private:
    const std::vector<std::unique_ptr<MatrixType>> &p;
  };



  class HermiteMultigrid::LevelMatrices : public MGMatrixBase<VectorType>
  {
  public:
    explicit LevelMatrices(const HermiteMultigrid &mg)
      : mg(mg)
    {}
    const MatrixType &
    operator[](const unsigned int level) const
    {
      return level + 1 == mg.n_levels() ? *mg.fine_matrix :
                                          *mg.coarse_matrices[level];
    }
    void
    vmult(const unsigned int level,
          VectorType        &dst,
          const VectorType  &src) const override
    {
      (*this)[level].vmult(dst, src);
    }
    void
    vmult_add(const unsigned int level,
              VectorType        &dst,
              const VectorType  &src) const override
    {
      (*this)[level].vmult_add(dst, src);
    }
    void
    Tvmult(const unsigned int level,
           VectorType        &dst,
           const VectorType  &src) const override
    {
      (*this)[level].Tvmult(dst, src);
    }
    void
    Tvmult_add(const unsigned int level,
               VectorType        &dst,
               const VectorType  &src) const override
    {
      (*this)[level].Tvmult_add(dst, src);
    }
    unsigned int
    get_minlevel() const override
    {
      return 0;
    }
    unsigned int
    get_maxlevel() const override
    {
      return mg.n_levels() - 1;
    }

  private:
    const HermiteMultigrid &mg;
  };



  /// Chebyshev smoothing around point Jacobi on every level but the
  /// coarsest.
  class HermiteMultigrid::Smoother : public MGSmootherBase<VectorType>
  {
  public:
    using Chebyshev = PreconditionChebyshev<MatrixType,
                                            VectorType,
                                            TrilinosWrappers::PreconditionJacobi>;

    /// (Re)initialise the smoothers of levels [first, end).
    void
    reinit(const LevelMatrices &matrices,
           const unsigned int   first,
           const unsigned int   end)
    {
      chebyshev.resize(end);
      for (unsigned int l = std::max(first, 1u); l < end; ++l)
        {
          const MatrixType               &A = matrices[l];
          typename Chebyshev::AdditionalData data;
          data.preconditioner =
            std::make_shared<TrilinosWrappers::PreconditionJacobi>();
          data.preconditioner->initialize(A);
          data.degree              = 4;
          data.smoothing_range     = 20.;
          data.eig_cg_n_iterations = 12;
          chebyshev[l]             = std::make_unique<Chebyshev>();
          chebyshev[l]->initialize(A, data);
        }
    }
    void
    clear() override
    {
      chebyshev.clear();
    }
    void
    smooth(const unsigned int level,
           VectorType        &u,
           const VectorType  &rhs) const override
    {
      chebyshev[level]->step(u, rhs);
    }
    void
    apply(const unsigned int level,
          VectorType        &u,
          const VectorType  &rhs) const override
    {
      chebyshev[level]->vmult(u, rhs);
    }

  private:
    std::vector<std::unique_ptr<Chebyshev>> chebyshev;
  };



  class HermiteMultigrid::CoarseSolver : public MGCoarseGridBase<VectorType>
  {
  public:
    CoarseSolver()
      : control(1, 0.)
      , solver(control, TrilinosWrappers::SolverDirect::AdditionalData(
                          false, "Amesos_Klu"))
    {}
    void
    reinit(const MatrixType &A)
    {
      solver.initialize(A);
    }
    void
    operator()(const unsigned int,
               VectorType       &dst,
               const VectorType &src) const override
    {
      solver.solve(dst, src);
    }

  private:
    SolverControl                                  control;
    mutable TrilinosWrappers::SolverDirect         solver;
  };



  HermiteMultigrid::HermiteMultigrid(const FE_BicubicHermite<2> &fe,
                                     MPI_Comm                    comm)
    : fe(fe)
    , comm(comm)
  {}



  HermiteMultigrid::~HermiteMultigrid() = default;



  void
  HermiteMultigrid::setup(
    const unsigned int                          nx,
    const unsigned int                          ny,
    const Tensor<1, 2>                         &h,
    const std::vector<types::global_dof_index> &vertex_dofs,
    const std::vector<bool>                    &constrained,
    const unsigned int                          max_coarse_dofs)
  {
    multigrid.reset();
    prolongation.clear();
    coarse_matrices.clear();
    fine_matrix = nullptr;

    // The level sizes, coarsest first.
    unsigned int L = 0;
    nx0 = nx, ny0 = ny;
    while (nx0 % 2 == 0 && ny0 % 2 == 0 && nx0 >= 4 && ny0 >= 4 &&
           4 * (nx0 + 1) * (ny0 + 1) > max_coarse_dofs)
      nx0 /= 2, ny0 /= 2, ++L;

    const types::global_dof_index n_fine = constrained.size();
    level_sets.assign(L + 1, IndexSet());
    for (unsigned int l = 0; l <= L; ++l)
      level_sets[l] =
        complete_index_set(l == L ? n_fine :
                                    4 * ((nx0 << l) + 1) * ((ny0 << l) + 1));

    // Dof index and constraint flag of dof k at vertex (i, j) of level l:
    // structured numbering below the finest level; the constraint pattern
    // of a vertex is the one of the same vertex on the finest level.
    const auto index = [&](unsigned int l, unsigned int i, unsigned int j,
                           unsigned int k) -> types::global_dof_index {
      const unsigned int n = (nx0 << l) + 1;
      return (l == L) ? vertex_dofs[4 * (i + (nx + 1) * j) + k] :
                        4 * (i + n * j) + k;
    };
    const auto is_constrained = [&](unsigned int l, unsigned int i,
                                    unsigned int j, unsigned int k) {
      const unsigned int s = L - l;
      return bool(
        constrained[vertex_dofs[4 * ((i << s) + (nx + 1) * (j << s)) + k]]);
    };

    std::vector<double>              values;
    std::vector<Tensor<1, 2>>        grads;
    std::vector<Tensor<2, 2>>        hessians;
    for (unsigned int l = 0; l < L; ++l)
      {
        const unsigned int ncx = nx0 << l, ncy = ny0 << l;
        const unsigned int nfx = 2 * ncx, nfy = 2 * ncy;
        Tensor<1, 2>       hc;
        hc[0] = h[0] * (1u << (L - l));
        hc[1] = h[1] * (1u << (L - l));

        // Visit every entry (fine dof, coarse dof, value) of P_l; called
        // once for the sparsity pattern and once for the values.
        const auto visit = [&](const auto &entry) {
          for (unsigned int J = 0; J <= nfy; ++J)
            for (unsigned int I = 0; I <= nfx; ++I)
              {
                if (I % 2 == 0 && J % 2 == 0)
                  {
                    for (unsigned int k = 0; k < 4; ++k)
                      entry(index(l + 1, I, J, k), index(l, I / 2, J / 2, k), 1.);
                    continue;
                  }
                const unsigned int ic = std::min(I / 2, ncx - 1);
                const unsigned int jc = std::min(J / 2, ncy - 1);
                const Point<2> unit(0.5 * (I - 2. * ic), 0.5 * (J - 2. * jc));
                fe.evaluate(unit, hc, values, grads, hessians);
                for (unsigned int k = 0; k < 4; ++k)
                  {
                    if (is_constrained(l + 1, I, J, k))
                      continue;
                    for (unsigned int m = 0; m < 16; ++m)
                      {
                        const unsigned int v = m / 4, km = m % 4;
                        const unsigned int vi = ic + v % 2, vj = jc + v / 2;
                        if (is_constrained(l, vi, vj, km))
                          continue;
                        const double a = (k == 0) ? values[m] :
                                         (k == 1) ? grads[m][0] :
                                         (k == 2) ? grads[m][1] :
                                                    hessians[m][0][1];
                        if (std::abs(a) > 1e-12)
                          entry(index(l + 1, I, J, k), index(l, vi, vj, km), a);
                      }
                  }
              }
        };
        DynamicSparsityPattern dsp(level_sets[l + 1].size(),
                                   level_sets[l].size());
        visit([&](types::global_dof_index i, types::global_dof_index j,
                  double) { dsp.add(i, j); });
        auto P = std::make_unique<MatrixType>();
        P->reinit(level_sets[l + 1], level_sets[l], dsp, comm);
        visit([&](types::global_dof_index i, types::global_dof_index j,
                  double a) { P->set(i, j, a); });
        P->compress(VectorOperation::insert);
        prolongation.push_back(std::move(P));
      }
    coarse_matrices.resize(L);
    for (auto &m : coarse_matrices)
      m = std::make_unique<MatrixType>();

    transfer       = std::make_unique<Transfer>(prolongation);
    level_matrices = std::make_unique<LevelMatrices>(*this);
    smoother       = std::make_unique<Smoother>();
    coarse         = std::make_unique<CoarseSolver>();
  }



  void
  HermiteMultigrid::reinit_matrix(const MatrixType &A, const bool galerkin)
  {
    Assert(transfer, ExcMessage("HermiteMultigrid::setup() first"));
    fine_matrix          = &A;
    const unsigned int L = prolongation.size();
    if (galerkin || !multigrid || L == 0)
      {
        MatrixType AP;
        for (unsigned int l = L; l-- > 0;)
          {
            const MatrixType &fine = (*level_matrices)[l + 1];
            fine.mmult(AP, *prolongation[l]);
            prolongation[l]->Tmmult(*coarse_matrices[l], AP);
          }
        smoother->reinit(*level_matrices, 1, L + 1);
        coarse->reinit((*level_matrices)[0]);
      }
    else
      smoother->reinit(*level_matrices, L, L + 1);
    if (!multigrid)
      multigrid = std::make_unique<Multigrid<VectorType>>(
        *level_matrices, *coarse, *transfer, *smoother, *smoother, 0, L);
  }



  void
  HermiteMultigrid::vmult(VectorType &dst, const VectorType &src) const
  {
    const unsigned int L = prolongation.size();
    if (multigrid->defect.max_level() != L)
      multigrid->defect.resize(0, L);
    for (unsigned int l = 0; l < L; ++l)
      {
        if (multigrid->defect[l].size() != level_sets[l].size())
          multigrid->defect[l].reinit(level_sets[l], comm);
        else
          multigrid->defect[l] = 0.;
      }
    multigrid->defect[L] = src;
    multigrid->vcycle();
    dst = multigrid->solution[L];
  }
} // namespace NitscheContact
