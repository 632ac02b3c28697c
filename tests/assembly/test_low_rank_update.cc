// The Woodbury solve of (A + B D B^T) x = r against a dense LU of the same
// matrix formed explicitly, with zero, positive and negative d_h (softening
// and stiffening), columns that touch the ground (one nonzero), and every
// solver backend as the factorisation of A.
#include <poundfe/input/engine_parameters.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/assembly/linear_solver.h>
#include <poundfe/assembly/low_rank_update.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/input/input_parameters.h>

#include <Eigen/Dense>

#include <cmath>

#include <random>

#include <boost/test/unit_test.hpp>

using namespace poundfe;

BOOST_AUTO_TEST_CASE(woodbury_solve_matches_dense_solve)
{
  const Analysis     analysis = prepare_analysis(read_parameters("input/two-buildings.prm"));
  const SparseMatrix A        = analysis.system.stiffness + 1e4 * analysis.system.mass;
  const unsigned int n        = A.rows();
  std::mt19937       random(11);
  std::uniform_int_distribution<int> row(0, n - 1);
  std::uniform_real_distribution<>   unit(-1, 1);
  std::vector<SparseColumn>          columns(12);
  for (unsigned int h = 0; h < columns.size(); ++h)
    {
      columns[h].rows   = {row(random), h % 4 == 0 ? -1 : row(random)};
      columns[h].values = {1.0, -1.0};
      if (columns[h].rows[0] == columns[h].rows[1])
        columns[h].rows[1] = -1;
    }
  Vector r(n);
  for (unsigned int i = 0; i < n; ++i)
    r[i] = unit(random);
  const double scale = A.diagonal().maxCoeff();
  for (const std::string &name : linear_solver_names())
    {
      auto solver = create_linear_solver(name);
      solver->analyze_and_factorize(A);
      LowRankUpdateSolver woodbury;
      woodbury.initialize(*solver, columns, n);
      for (unsigned int trial = 0; trial < 3; ++trial)
        {
          std::vector<double> d(columns.size());
          for (unsigned int h = 0; h < d.size(); ++h)
            d[h] = (h % 3 == trial) ? 0.0 : 0.3 * scale * unit(random); // some inactive
          Eigen::MatrixXd dense = Eigen::MatrixXd(A);
          for (unsigned int h = 0; h < d.size(); ++h)
            for (unsigned int i = 0; i < 2; ++i)
              for (unsigned int j = 0; j < 2; ++j)
                if (columns[h].rows[i] >= 0 && columns[h].rows[j] >= 0)
                  dense(columns[h].rows[i], columns[h].rows[j]) +=
                    d[h] * columns[h].values[i] * columns[h].values[j];
          const Vector expected = dense.partialPivLu().solve(r);
          Vector       x;
          woodbury.solve(r, d, x);
          BOOST_TEST_INFO(name << " trial " << trial);
          // both are backward stable; the condition number of A + B D B^T
          // here is ~1e6, so agreement to 1e-8 is what double precision gives
          BOOST_TEST((x - expected).norm() / expected.norm() < 1e-8);
          BOOST_TEST(woodbury.n_active() == 8u);
        }
    }
}

BOOST_AUTO_TEST_CASE(woodbury_solve_with_nonsymmetric_blocks_matches_dense_lu)
{
  // D block diagonal with blocks of 1, 2 and 3 columns, dense and
  // nonsymmetric, one of them singular, some of them zero (inactive); the
  // columns have up to three nonzeros, some on the ground (row -1).
  const Analysis     analysis = prepare_analysis(read_parameters("input/two-buildings.prm"));
  const SparseMatrix A        = analysis.system.stiffness + 1e4 * analysis.system.mass;
  const unsigned int n        = A.rows();
  std::mt19937       random(17);
  std::uniform_int_distribution<int> row(0, n - 1);
  std::uniform_real_distribution<>   unit(-1, 1);
  const std::vector<unsigned int>    sizes{1, 2, 3, 1, 2, 3, 2};
  std::vector<SparseColumn>          columns;
  for (const unsigned int size : sizes)
    for (unsigned int j = 0; j < size; ++j)
      {
        SparseColumn column;
        column.rows   = {row(random), columns.size() % 5 == 0 ? -1 : row(random), row(random)};
        column.values = {unit(random), unit(random), unit(random)};
        columns.push_back(column);
      }
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, columns.size());
  for (unsigned int c = 0; c < columns.size(); ++c)
    for (unsigned int i = 0; i < 3; ++i)
      if (columns[c].rows[i] >= 0)
        B(columns[c].rows[i], c) += columns[c].values[i];
  Vector r(n);
  for (unsigned int i = 0; i < n; ++i)
    r[i] = unit(random);
  const double scale = A.diagonal().maxCoeff();
  for (const std::string &name : {std::string("eigen-ldlt"), std::string("umfpack")})
    {
      auto solver = create_linear_solver(name);
      solver->analyze_and_factorize(A);
      LowRankUpdateSolver woodbury;
      woodbury.initialize(*solver, columns, n, sizes);
      BOOST_TEST(woodbury.n_columns() == 14u);
      for (unsigned int trial = 0; trial < 3; ++trial)
        {
          std::vector<double> d;
          Eigen::MatrixXd     D = Eigen::MatrixXd::Zero(columns.size(), columns.size());
          unsigned int        first = 0, n_active = 0;
          for (unsigned int e = 0; e < sizes.size(); ++e)
            {
              const unsigned int s = sizes[e];
              Eigen::MatrixXd    block(s, s);
              for (unsigned int q = 0; q < s * s; ++q)
                block.data()[q] = (e % 3 == trial) ? 0.0 : 0.3 * scale * unit(random);
              if (e == 5 && trial != 2) // a singular block: rank 2 of 3
                block.col(2) = block.col(0) + block.col(1);
              if (e % 3 != trial)
                n_active += s;
              d.insert(d.end(), block.data(), block.data() + s * s);
              D.block(first, first, s, s) = block;
              first += s;
            }
          const Eigen::MatrixXd dense    = Eigen::MatrixXd(A) + B * D * B.transpose();
          const Vector          expected = dense.partialPivLu().solve(r);
          Vector                x;
          woodbury.solve(r, d, x);
          BOOST_TEST_INFO(name << " trial " << trial);
          const double error = (x - expected).norm() / expected.norm();
          BOOST_TEST_MESSAGE(name << " trial " << trial << ": relative difference " << error);
          BOOST_TEST(error < 1e-8);
          BOOST_TEST(woodbury.n_active() == n_active);
        }
    }
}

BOOST_AUTO_TEST_CASE(woodbury_solve_reusing_its_capacitance_matrix_is_a_fresh_solve)
{
  // A solve whose active blocks of D are those of the last one to the bit
  // reuses the LU of I + D_a G_aa (modal damping's constant D, a linear
  // law's tangent at every iteration). Against a fresh solver (no LU to
  // reuse) on the same A: the same x to the bit, whatever came before: the
  // same d again, a changed d, an inactive block, d back to an earlier one,
  // one active column in between (its elimination overwrites S);
  // and within 1e-8 of a dense LU of A + B D B^T, as above.
  const Analysis     analysis = prepare_analysis(read_parameters("input/two-buildings.prm"));
  const SparseMatrix A        = analysis.system.stiffness + 1e4 * analysis.system.mass;
  const unsigned int n        = A.rows();
  std::mt19937       random(23);
  std::uniform_int_distribution<int> row(0, n - 1);
  std::uniform_real_distribution<>   unit(-1, 1);
  std::vector<SparseColumn>          columns(6);
  for (unsigned int h = 0; h < columns.size(); ++h)
    columns[h] = SparseColumn{{row(random), h % 3 == 0 ? -1 : row(random)}, {1.0, -1.0}};
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, columns.size());
  for (unsigned int h = 0; h < columns.size(); ++h)
    for (unsigned int i = 0; i < 2; ++i)
      if (columns[h].rows[i] >= 0)
        B(columns[h].rows[i], h) += columns[h].values[i];
  const double        scale = A.diagonal().maxCoeff();
  std::vector<double> first(columns.size()), second(columns.size()), single(columns.size());
  for (unsigned int h = 0; h < columns.size(); ++h)
    {
      first[h]  = 0.3 * scale * unit(random);
      second[h] = h == 2 ? 0.0 : 0.3 * scale * unit(random); // one block inactive
    }
  single[4] = first[4]; // one active column, eliminated afresh: not the LU of `first`
  auto solver = create_linear_solver("eigen-ldlt");
  solver->analyze_and_factorize(A);
  LowRankUpdateSolver reused;
  reused.initialize(*solver, columns, n);
  const std::vector<const std::vector<double> *> sequence{&first, &first, &second, &second,
                                                          &first, &single, &first, &first};
  for (unsigned int call = 0; call < sequence.size(); ++call)
    {
      const std::vector<double> &d = *sequence[call];
      Vector r(n);
      for (unsigned int i = 0; i < n; ++i)
        r[i] = unit(random);
      LowRankUpdateSolver fresh;
      fresh.initialize(*solver, columns, n);
      Vector x, expected;
      BOOST_REQUIRE(reused.solve(r, d, x));
      BOOST_REQUIRE(fresh.solve(r, d, expected));
      BOOST_TEST_INFO("call " << call);
      BOOST_TEST((x.array() == expected.array()).all()); // to the bit
      Eigen::MatrixXd D = Eigen::MatrixXd::Zero(columns.size(), columns.size());
      for (unsigned int h = 0; h < d.size(); ++h)
        D(h, h) = d[h];
      const Vector dense = (Eigen::MatrixXd(A) + B * D * B.transpose()).partialPivLu().solve(r);
      BOOST_TEST((x - dense).norm() / dense.norm() < 1e-8); // as above
    }
}

BOOST_AUTO_TEST_CASE(woodbury_solve_with_one_active_column_is_sherman_morrison)
{
  // One active column (a single storey's law, one gap in contact): the
  // solve is x = y - w (d b^T y) / (1 + d b^T w), y = A^{-1} r, w = A^{-1} b,
  // formed here from the same factorisation with b^T y and b^T w summed over
  // b's entries in order, as the solver sums them: equal to the bit. And
  // against a dense LU of A + d b b^T (1e-8, as above).
  const Analysis     analysis = prepare_analysis(read_parameters("input/two-buildings.prm"));
  const SparseMatrix A        = analysis.system.stiffness + 1e4 * analysis.system.mass;
  const unsigned int n        = A.rows();
  std::mt19937       random(23);
  std::uniform_real_distribution<> unit(-1, 1);
  const std::vector<SparseColumn>  columns{{{3, 7}, {1.0, -1.0}}, {{5, -1}, {1.0, -1.0}}};
  auto solver = create_linear_solver("eigen-ldlt");
  solver->analyze_and_factorize(A);
  LowRankUpdateSolver woodbury;
  woodbury.initialize(*solver, columns, n);
  Vector r(n), b = Vector::Zero(n), y, w;
  for (unsigned int i = 0; i < n; ++i)
    r[i] = unit(random);
  b[3] += 1.0;
  b[7] += -1.0;
  solver->solve(r, y);
  solver->solve(b, w);
  for (const double d : {0.3, -0.2, 5.0})
    {
      const double dk = d * A.diagonal().maxCoeff();
      Vector       x;
      BOOST_REQUIRE(woodbury.solve(r, {dk, 0.0}, x));
      const double bty = (0.0 + 1.0 * y[3]) + -1.0 * y[7];
      const double btw = (0.0 + 1.0 * w[3]) + -1.0 * w[7];
      Vector       expected = y;
      expected.noalias() -= (dk * bty / (1.0 + dk * btw)) * w;
      BOOST_TEST_INFO("d = " << d);
      BOOST_TEST(woodbury.n_active() == 1u);
      BOOST_TEST((x.array() == expected.array()).all()); // to the bit
      const Vector dense =
        (Eigen::MatrixXd(A) + dk * b * b.transpose()).partialPivLu().solve(r);
      BOOST_TEST((x - dense).norm() / dense.norm() < 1e-8);
    }
}

namespace
{
  /// A's factorisation that throws NumericalError at its `throw_at`-th
  /// solve (counting from 1; 0: never): a base solver that fails while a
  /// column of W is computed.
  class FailingSolver : public LinearSolver
  {
  public:
    explicit FailingSolver(LinearSolver &factorised) : factorised(factorised) {}
    void analyze(const SparseMatrix &) override {}
    void factorize(const SparseMatrix &) override {}
    void
    solve(const Vector &b, Vector &x) override
    {
      if (++n_solves == throw_at)
        throw NumericalError("a solve that fails on purpose");
      factorised.solve(b, x);
    }
    std::string name() const override { return "failing"; }

    unsigned int throw_at = 0;
    unsigned int n_solves = 0;

  private:
    LinearSolver &factorised;
  };
} // namespace

BOOST_AUTO_TEST_CASE(woodbury_solve_after_a_throw_is_a_fresh_solve)
{
  // A throw inside the several-column path leaves nothing stale: the next
  // solve is a fresh solver's to the bit. Two throws are forced: (1) a zero
  // pivot of I + D_a G_aa (a NaN entry of D: no pivot is > 0) after the LU
  // of `first` was stored, then `first` again; (2) with two slots of W for
  // three columns, A's solve of a missing column throws while the slot it
  // would take still holds a column of the stored LU, then `first` (the
  // columns of that LU) again. Before (2) was made safe, the slot was
  // listed as taken by a column noted as not kept, and the next search for
  // room ran past the last slot.
  const Analysis     analysis = prepare_analysis(read_parameters("input/two-buildings.prm"));
  const SparseMatrix A        = analysis.system.stiffness + 1e4 * analysis.system.mass;
  const unsigned int n        = A.rows();
  const double       scale    = A.diagonal().maxCoeff();
  const std::vector<SparseColumn> columns{{{3, 7}, {1.0, -1.0}}, {{5, -1}, {1.0, -1.0}},
                                          {{2, 6}, {1.0, -1.0}}};
  const std::vector<double> first{0.3 * scale, -0.2 * scale, 0.0};
  const std::vector<double> singular{std::nan(""), -0.2 * scale, 0.0};
  const std::vector<double> third{0.0, 0.0, 0.4 * scale};
  auto solver = create_linear_solver("eigen-ldlt");
  solver->analyze_and_factorize(A);
  Vector r(n);
  for (unsigned int i = 0; i < n; ++i)
    r[i] = std::sin(1.0 + i);
  const auto fresh_solve = [&](const std::vector<double> &d) {
    LowRankUpdateSolver fresh;
    fresh.initialize(*solver, columns, n);
    Vector x;
    BOOST_REQUIRE(fresh.solve(r, d, x));
    return x;
  };
  const Vector expected = fresh_solve(first);
  for (const unsigned int max_columns : {0u, 2u})
    {
      BOOST_TEST_INFO("max_columns " << max_columns);
      FailingSolver failing(*solver);
      LowRankUpdateSolver woodbury;
      woodbury.initialize(failing, columns, n, {}, max_columns);
      Vector x;
      BOOST_REQUIRE(woodbury.solve(r, first, x)); // its LU stored
      BOOST_CHECK_THROW(woodbury.solve(r, singular, x), NumericalError);
      BOOST_REQUIRE(woodbury.solve(r, first, x));
      BOOST_TEST((x.array() == expected.array()).all());
      if (max_columns == 0) // every column computed at the start: no solve of one to fail
        continue;
      failing.throw_at = failing.n_solves + 1; // column 2's, before A^{-1} r
      BOOST_CHECK_THROW(woodbury.solve(r, third, x), NumericalError);
      BOOST_REQUIRE(woodbury.solve(r, first, x));
      BOOST_TEST((x.array() == expected.array()).all());
      BOOST_REQUIRE(woodbury.solve(r, third, x)); // column 2 computed now
      BOOST_TEST((x.array() == fresh_solve(third).array()).all());
    }
}
