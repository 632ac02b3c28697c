// muParser wrapped behind the interface of include/poundfe/reliability/limit_state.h.
#include <poundfe/reliability/limit_state.h>

#include <muParser.h>

#include <cctype>
#include <stdexcept>

namespace poundfe
{
  struct LimitStateExpression::Parser
  {
    std::string         text;
    std::vector<double> values; // the parser reads the variables from here
    std::vector<std::string> names;
    mu::Parser          parser;
  };

  bool
  is_identifier(const std::string &name)
  {
    if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_'))
      return false;
    for (const char c : name)
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_'))
        return false;
    return true;
  }

  LimitStateExpression::LimitStateExpression(
    const std::string &expression, const std::vector<std::string> &variables,
    const std::vector<std::pair<std::string, double>> &constants)
    : parser(std::make_unique<Parser>())
  {
    parser->text  = expression;
    parser->names = variables;
    parser->values.assign(variables.size(), 1.0);
    try
      {
        for (std::size_t i = 0; i < variables.size(); ++i)
          parser->parser.DefineVar(variables[i], &parser->values[i]);
        for (const auto &[name, value] : constants)
          parser->parser.DefineConst(name, value);
        parser->parser.SetExpr(expression);
        parser->parser.Eval(); // muParser parses at the first evaluation
      }
    catch (const mu::Parser::exception_type &e)
      {
        std::string message = e.GetMsg();
        if (!message.empty() && message.back() == '.')
          message.pop_back();
        throw std::invalid_argument("the expression '" + expression +
                                    "' does not parse: " + message);
      }
  }

  LimitStateExpression::~LimitStateExpression()                                      = default;
  LimitStateExpression::LimitStateExpression(LimitStateExpression &&) noexcept            = default;
  LimitStateExpression &LimitStateExpression::operator=(LimitStateExpression &&) noexcept = default;

  double
  LimitStateExpression::operator()(const double *x) const
  {
    std::copy(x, x + parser->values.size(), parser->values.begin());
    return parser->parser.Eval();
  }

  const std::string &
  LimitStateExpression::expression() const
  {
    return parser->text;
  }

  std::vector<unsigned int>
  LimitStateExpression::used_variables() const
  {
    std::vector<unsigned int> used;
    const mu::varmap_type    &map = parser->parser.GetUsedVar();
    for (unsigned int i = 0; i < parser->names.size(); ++i)
      if (map.count(parser->names[i]))
        used.push_back(i);
    return used;
  }
} // namespace poundfe
