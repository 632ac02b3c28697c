// A limit-state function g(x) written as an expression over named random
// variables and constants; failure is g <= 0.
//   e.g. the cantilever of the thesis (eq. 2.44):
//   sigma_s - 6*sx*l/(w^2*h) - 6*sy*l/(w*h^2)
// Parsed by muParser (2.3, the library deal.II is built with,
// DEAL_II_WITH_MUPARSER), which compiles the expression to byte code once;
// each evaluation copies the values into the parser's variables and runs the
// byte code. deal.II's own FunctionParser is not used: it binds its
// variables to the coordinates of a Point<dim> (dim <= 3) and the time, and a
// limit state has any number of named variables.
// Syntax: + - * / ^, comparisons, ?:, sin cos tan asin acos atan sinh cosh
// tanh exp ln log10 sqrt abs sign rint min max sum avg, constants _pi _e.
#ifndef poundfe_reliability_limit_state_h
#define poundfe_reliability_limit_state_h

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace poundfe
{
  class LimitStateExpression
  {
  public:
    /// `variables`: the names of x's entries, in order; `constants`: names
    /// with fixed values. Throws std::invalid_argument with the parser's
    /// message (syntax error, unknown name and where it is) when the
    /// expression cannot be evaluated.
    LimitStateExpression(const std::string                                  &expression,
                         const std::vector<std::string>                     &variables,
                         const std::vector<std::pair<std::string, double>> &constants = {});
    ~LimitStateExpression();
    LimitStateExpression(LimitStateExpression &&) noexcept;
    LimitStateExpression &operator=(LimitStateExpression &&) noexcept;

    /// g(x); x holds one value per variable. Not thread-safe (one parser
    /// state per object).
    double operator()(const double *x) const;
    double operator()(const std::vector<double> &x) const { return (*this)(x.data()); }

    const std::string &expression() const;
    /// Indices of the variables the expression uses.
    std::vector<unsigned int> used_variables() const;

  private:
    struct Parser;
    std::unique_ptr<Parser> parser;
  };

  /// Whether `name` can name a variable of an expression (a letter or '_'
  /// then letters, digits, '_').
  bool is_identifier(const std::string &name);
} // namespace poundfe

#endif
