// The analysis and query commands of OpenSees scripts, with OpenSees 3.8's
// argument syntax: constraints, numberer, system, test, algorithm,
// integrator, analysis, analyze, eigen, wipeAnalysis, getTime, nodeDisp,
// nodeVel, nodeAccel, nodeReaction, reactions, getNodeTags, getEleTags,
// nodeCoord, eleForce, eleResponse, testIter, testNorm, getNP, getPID. A
// component the script leaves out takes OpenSees's default (NormUnbalance 1e-6 25, Newton, Newmark 0.5 0.25 or
// LoadControl 1), with OpenSees's warning.
#include "opensees_tcl.h"

#include <poundfe/base/launched_job.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <regex>
#include <optional>
#include <ostream>

namespace poundfe
{
  namespace opensees_tcl
  {
    namespace
    {
      using opensees::ScriptError;

      void
      check_done(Words &w)
      {
        if (!w.done())
          unsupported(w.name + " option '" + w.peek() + "'");
      }

      /// The script changed a component: the analysis, if any, takes it,
      /// but keeps its kind and its constraint handler (OpenSees 3.8's
      /// `constraints` makes the handler of the next `analysis`).
      void
      reconfigure(Session &s)
      {
        if (s.analysis)
          {
            const opensees::AnalysisOptions &now = s.analysis->options();
            opensees::AnalysisOptions        o   = s.options;
            o.transient                          = now.transient;
            o.transformation                     = now.transformation;
            o.penalty                            = now.penalty;
            o.lagrange                           = now.lagrange;
            o.alpha_sp                           = now.alpha_sp;
            o.alpha_mp                           = now.alpha_mp;
            s.analysis->configure(o);
          }
      }

      /// The command's one word, one of `names`.
      std::string
      accept_names(Words &w, const std::vector<std::string> &names)
      {
        const std::string name = w.word("the type");
        if (std::find(names.begin(), names.end(), name) == names.end())
          unsupported(w.name + " " + name);
        check_done(w);
        return name;
      }

      void
      test(Session &s, Words &w)
      {
        using Kind        = opensees::ConvergenceTest::Kind;
        const std::string type = w.word("the test's type");
        opensees::ConvergenceTest t;
        if (type == "NormDispIncr")
          t.kind = Kind::norm_disp_incr;
        else if (type == "NormUnbalance")
          t.kind = Kind::norm_unbalance;
        else if (type == "EnergyIncr")
          t.kind = Kind::energy_incr;
        else if (type == "RelativeNormDispIncr")
          t.kind = Kind::relative_norm_disp_incr;
        else
          unsupported("test " + type);
        t.tolerance      = w.real("the tolerance");
        t.max_iterations = w.integer("the number of iterations");
        if (!w.done())
          t.print_flag = w.integer("the print flag");
        if (t.print_flag != 0 && t.print_flag != 1 && t.print_flag != 2 && t.print_flag != 5)
          unsupported("test print flag " + std::to_string(t.print_flag));
        if (!w.done() && w.integer("the norm type") != 2)
          unsupported("test norm type other than 2");
        check_done(w);
        s.options.test = t;
        s.has_test     = true;
        reconfigure(s);
      }

      /// NewtonLineSearch's options (OpenSees's defaults: -tol 0.8 -maxIter
      /// 10 -minEta 0.1 -maxEta 10 -pFlag 1 -type InitialInterpolated).
      void
      line_search_options(opensees::AnalysisOptions::LineSearch &p, Words &w)
      {
        p = opensees::AnalysisOptions::LineSearch();
        while (!w.done())
          {
            const std::string option = w.word("an option");
            if (option == "-tol")
              p.tolerance = w.real("the line search tolerance");
            else if (option == "-maxIter")
              {
                const int n = w.integer("the line search's iterations");
                if (n < 1)
                  throw ScriptError("NewtonLineSearch needs -maxIter >= 1");
                p.max_iterations = n;
              }
            else if (option == "-minEta")
              p.min_eta = w.real("minEta");
            else if (option == "-maxEta")
              p.max_eta = w.real("maxEta");
            else if (option == "-pFlag")
              p.print = w.integer("the print flag") == 0;
            else if (option == "-type")
              {
                const std::string type = w.word("the line search's type");
                if (type != "InitialInterpolated")
                  unsupported("algorithm NewtonLineSearch -type " + type);
              }
            else
              unsupported("algorithm NewtonLineSearch option '" + option + "'");
          }
        if (!(p.tolerance > 0))
          throw ScriptError("NewtonLineSearch needs -tol > 0");
        if (!(p.min_eta > 0 && p.min_eta <= p.max_eta))
          throw ScriptError("NewtonLineSearch needs 0 < -minEta <= -maxEta");
      }

      /// KrylovNewton <-maxDim N> <-iterate current> <-increment current>
      /// (OpenSees's defaults: 3, the current tangent).
      void
      krylov_options(opensees::AnalysisOptions &o, Words &w)
      {
        o.krylov_dimension = 3;
        while (!w.done())
          {
            const std::string option = w.word("an option");
            if (option == "-maxDim")
              {
                const int n = w.integer("-maxDim");
                if (n < 0)
                  throw ScriptError("KrylovNewton needs -maxDim >= 0");
                o.krylov_dimension = n;
              }
            else if (option == "-iterate" || option == "-increment")
              {
                const std::string tangent = w.word("the tangent");
                if (tangent != "current")
                  unsupported("algorithm KrylovNewton " + option + " " + tangent);
              }
            else
              unsupported("algorithm KrylovNewton option '" + option + "'");
          }
      }

      /// BFGS <-count N> (OpenSees's default 10, the current tangent).
      void
      bfgs_options(opensees::AnalysisOptions &o, Words &w)
      {
        o.bfgs_count = 10;
        while (!w.done())
          {
            const std::string option = w.word("an option");
            if (option != "-count")
              unsupported("algorithm BFGS option '" + option + "'");
            const int n = w.integer("-count");
            if (n < 1)
              throw ScriptError("BFGS needs -count >= 1");
            o.bfgs_count = n;
          }
      }

      void
      algorithm(Session &s, Words &w)
      {
        using Algorithm             = opensees::AnalysisOptions::Algorithm;
        const std::string         type = w.word("the algorithm's type");
        opensees::AnalysisOptions o    = s.options; // stored once every word is checked
        if (type == "Linear")
          o.algorithm = Algorithm::linear;
        else if (type == "Newton")
          o.algorithm = Algorithm::newton;
        else if (type == "ModifiedNewton")
          o.algorithm = Algorithm::modified_newton;
        else if (type == "NewtonLineSearch")
          {
            o.algorithm = Algorithm::newton_line_search;
            line_search_options(o.line_search, w);
          }
        else if (type == "KrylovNewton")
          {
            o.algorithm = Algorithm::krylov_newton;
            krylov_options(o, w);
          }
        else if (type == "BFGS")
          {
            o.algorithm = Algorithm::bfgs;
            bfgs_options(o, w);
          }
        else
          unsupported("algorithm " + type);
        check_done(w);
        s.options       = o;
        s.has_algorithm = true;
        reconfigure(s);
      }

      /// DisplacementControl node dof dU <Jd minIncr maxIncr>.
      void
      displacement_control(const opensees::Domain &domain, opensees::AnalysisOptions &o, Words &w)
      {
        o.control_node = domain.node(w.integer("the node")).tag;
        const int dof                = w.integer("the DOF");
        if (dof < 1 || dof > static_cast<int>(domain.ndf))
          throw ScriptError("DOF " + std::to_string(dof) + " is not one of 1 to ndf");
        o.control_dof    = dof - 1;
        o.d_u            = w.real("the displacement increment");
        o.d_u_iterations = 1;
        o.d_u_min = o.d_u_max = o.d_u;
        if (!w.done() && w.peek() != "-initial")
          {
            o.d_u_iterations = w.integer("Jd");
            o.d_u_min        = w.real("the smallest increment");
            o.d_u_max        = w.real("the largest increment");
          }
        if (w.peek() == "-initial")
          unsupported("integrator DisplacementControl -initial");
        if (o.d_u_iterations < 1)
          throw ScriptError("Jd must be >= 1");
        o.displacement_control = true;
      }

      /// constraints Plain | Transformation | Penalty alphaSP alphaMP |
      /// Lagrange <alphaSP alphaMP>. Lagrange's multipliers meet linear
      /// constraints exactly, so its displacements are Transformation's,
      /// which gives them (its factors scale the multipliers alone). As in
      /// OpenSees 3.8 the handler is the next `analysis` command's.
      void
      constraint_handler(Session &s, Words &w)
      {
        const std::string type = w.word("the handler's type");
        if (type != "Plain" && type != "Transformation" && type != "Penalty" &&
            type != "Lagrange")
          unsupported("constraints " + type);
        double alpha_sp = 0, alpha_mp = 0;
        if (type == "Penalty")
          {
            alpha_sp = w.real("alphaSP");
            alpha_mp = w.real("alphaMP");
            if (!(alpha_sp > 0 && alpha_mp > 0))
              throw ScriptError("Penalty needs alphaSP > 0 and alphaMP > 0");
          }
        else if (type == "Lagrange" && !w.done())
          {
            w.real("alphaSP");
            w.real("alphaMP");
          }
        check_done(w);
        opensees::AnalysisOptions &o = s.options; // every word checked
        o.transformation             = type == "Transformation" || type == "Lagrange";
        o.penalty                    = type == "Penalty";
        o.lagrange                   = type == "Lagrange";
        o.alpha_sp                   = alpha_sp;
        o.alpha_mp                   = alpha_mp;
      }

      /// ArcLength s alpha (OpenSees 3.8's interpreter takes both).
      void
      arc_length(opensees::AnalysisOptions &o, Words &w)
      {
        o.arc_s     = w.real("the arc length");
        o.arc_alpha = w.real("alpha");
        if (!(o.arc_s > 0))
          throw ScriptError("ArcLength needs an arc length > 0");
        o.displacement_control = false;
      }

      /// HHT alpha <gamma beta> (OpenSees's alpha: 1 is Newmark's average
      /// acceleration, 2/3 the most dissipative; by default gamma = 3/2 -
      /// alpha, beta = (2 - alpha)^2 / 4).
      void
      hht(opensees::AnalysisOptions &o, Words &w)
      {
        o.alpha                      = w.real("alpha");
        o.hht                        = true;
        o.gamma                      = 1.5 - o.alpha;
        o.beta                       = 0.25 * (2 - o.alpha) * (2 - o.alpha);
        if (!w.done())
          {
            o.gamma = w.real("gamma");
            o.beta  = w.real("beta");
          }
        if (!(o.alpha > 0 && o.alpha <= 1))
          throw ScriptError("HHT needs 0 < alpha <= 1");
        if (!(o.beta > 0 && o.gamma > 0))
          throw ScriptError("HHT needs beta > 0 and gamma > 0");
      }

      /// LoadControl dLambda <numIter minLambda maxLambda>.
      void
      load_control(opensees::AnalysisOptions &o, Words &w)
      {
        o.d_lambda          = w.real("the load increment");
        o.lambda_iterations = 1;
        o.lambda_min = o.lambda_max = o.d_lambda;
        if (!w.done())
          {
            o.lambda_iterations = w.integer("the number of iterations");
            o.lambda_min        = w.real("the smallest increment");
            o.lambda_max        = w.real("the largest increment");
          }
        o.displacement_control = false;
      }

      void
      integrator(Session &s, Words &w)
      {
        const std::string         type = w.word("the integrator's type");
        opensees::AnalysisOptions o    = s.options; // stored once every word is checked
        o.arc_length                   = type == "ArcLength";
        const bool transient           = type == "Newmark" || type == "HHT";
        if (type == "Newmark")
          {
            o.gamma = w.real("gamma");
            o.beta  = w.real("beta");
            o.alpha = 1;
            o.hht   = false;
            if (!(o.beta > 0))
              throw ScriptError("Newmark needs beta > 0");
          }
        else if (type == "HHT")
          hht(o, w);
        else if (type == "LoadControl")
          load_control(o, w);
        else if (type == "DisplacementControl")
          displacement_control(s.domain, o, w);
        else if (type == "ArcLength")
          arc_length(o, w);
        else
          unsupported("integrator " + type);
        check_done(w);
        ++o.integrator_serial;
        s.options = o;
        (transient ? s.has_transient_integrator : s.has_static_integrator) = true;
        reconfigure(s);
      }

      /// OpenSees's defaults for what the script left out, with its warnings.
      void
      default_components(Session &s, const bool transient)
      {
        const std::string kind = transient ? "Transient" : "Static";
        if (!s.has_test)
          s.warnings << "WARNING analysis " << kind
                     << " - no ConvergenceTest yet specified, NormUnbalance default will be "
                        "used\n";
        if (!s.has_algorithm)
          s.warnings << "WARNING analysis " << kind
                     << " - no Algorithm yet specified, NewtonRaphson default will be used\n";
        if (transient && !s.has_transient_integrator)
          {
            s.warnings << "WARNING analysis Transient - no Integrator specified, Newmark(0.5, "
                          "0.25) default will be used\n";
            s.options.gamma = 0.5;
            s.options.beta  = 0.25;
            s.options.alpha = 1;
            s.options.hht   = false;
          }
        if (!transient && !s.has_static_integrator)
          {
            s.warnings << "WARNING analysis Static - no Integrator specified, LoadControl(1.0) "
                          "default will be used\n";
            s.options.d_lambda = s.options.lambda_min = s.options.lambda_max = 1;
            s.options.lambda_iterations = 1;
          }
      }

      void
      add_counts(Session &s)
      {
        if (!s.analysis)
          return;
        s.counts.steps += s.analysis->counts.steps;
        s.counts.iterations += s.analysis->counts.iterations;
        s.counts.factorizations += s.analysis->counts.factorizations;
        s.counts.failed_steps += s.analysis->counts.failed_steps;
      }

      void
      analysis(Session &s, Words &w)
      {
        const std::string type = w.word("the analysis' type");
        // OpenSees's three names of VariableTimeStepDirectIntegrationAnalysis
        const bool variable = type == "VariableTransient" || type == "VariableTimeStepTransient" ||
                              type == "TransientWithVariableTimeStep";
        if (type != "Static" && type != "Transient" && !variable)
          unsupported("analysis " + type);
        check_done(w);
        if (s.domain.ndf == 0)
          throw ScriptError("no model yet");
        const bool transient = type == "Transient" || variable;
        default_components(s, transient);
        s.options.transient          = transient;
        s.options.variable_time_step = variable;
        add_counts(s);
        s.analysis = std::make_unique<opensees::Analysis>(s.domain, s.options);
      }

      /// analyze's dtMin dtMax Jd (when given: a VariableTransient analysis
      /// only, as OpenSees's analyze).
      std::optional<opensees::Analysis::VariableSteps>
      variable_steps(Session &s, Words &w, const int steps, const double dt)
      {
        if (w.done() || w.peek() == "-noFlush")
          return std::nullopt;
        if (!s.analysis->options().variable_time_step)
          throw ScriptError("dtMin dtMax Jd given to an analysis that is not VariableTransient "
                            "(no variable time step transient analysis object constructed)");
        opensees::Analysis::VariableSteps v;
        v.n_steps = std::max(steps, 0);
        v.dt      = dt;
        v.dt_min  = w.real("dtMin");
        v.dt_max  = w.real("dtMax");
        v.jd      = w.integer("Jd");
        if (!(v.dt_min > 0) || !(v.dt_max >= v.dt_min))
          throw ScriptError("dtMin must be > 0 and dtMax >= dtMin");
        if (v.jd < 1)
          throw ScriptError("Jd must be >= 1");
        return v;
      }

      void
      analyze(Session &s, Words &w)
      {
        if (!s.analysis)
          throw ScriptError("no analysis yet: the script must call 'analysis Static|Transient'");
        const int steps = w.integer("the number of steps");
        double    dt    = 0;
        if (s.analysis->options().transient)
          {
            dt = w.real("the time step");
            if (!(dt > 0))
              throw ScriptError("the time step must be > 0");
          }
        const std::optional<opensees::Analysis::VariableSteps> variable =
          variable_steps(s, w, steps, dt);
        if (!w.done() && w.peek() == "-noFlush") // the files are written at the end anyway
          w.word("-noFlush");
        check_done(w);
        if (steps < 0)
          throw ScriptError("the number of steps must be >= 0");
        if (s.analysis->options().transient)
          s.domain.time_step = dt; // OpenSees's ops_Dt (ViscousDamper), the first step's
        s.node_vectors.analysed = s.node_vectors.analysed || steps > 0;
        s.node_vectors.transient_analysed =
          s.node_vectors.transient_analysed || (steps > 0 && s.analysis->options().transient);
        s.analysis->max_cuts = s.max_cuts;
        if (s.event_levels > 0 || s.analysis->events) // nothing paid while it is off
          begin_locating(s);
        const bool transient = s.analysis->options().transient;
        if (transient)
          begin_observing(s);
        const auto record = [&]() {
          s.record();
          if (transient)
            observe_step(s);
        };
        const auto warn   = [&](const std::string &why) {
          // the test's and the line search's own lines are not warnings
          const bool report = why.compare(0, 5, "CTest") == 0 ||
                              why.compare(0, 19, "InitialInterpolated") == 0;
          s.warnings << (report ? "" : "WARNING ") << why << "\n";
        };
        const int result = variable ? s.analysis->analyze_variable(*variable, record, warn) :
                                      s.analysis->analyze(steps, dt, record, warn);
        Tcl_SetObjResult(w.interp, Tcl_NewIntObj(result));
      }

      void
      eigen(Session &s, Words &w)
      {
        while (w.peek().size() > 1 && w.peek()[0] == '-')
          {
            const std::string option = w.word("an option");
            if (option != "-genBandArpack" && option != "-fullGenLapack" &&
                option != "-symmBandLapack")
              unsupported("eigen option '" + option + "'");
          }
        const int n = w.integer("the number of modes");
        check_done(w);
        if (n < 1)
          throw ScriptError("the number of modes must be >= 1");
        if (s.domain.ndf == 0)
          throw ScriptError("no model yet");
        if (!s.analysis)
          {
            opensees::Analysis modal(s.domain, s.options);
            set_result(w.interp, modal.eigenvalues(n));
          }
        else
          set_result(w.interp, s.analysis->eigenvalues(n));
      }

      /// modalDamping zeta... (modalDampingQ: `in_tangent` false): one
      /// factor for every mode of the last `eigen`, or one per mode (0 for
      /// those left out, extras ignored), with OpenSees 3.8's warnings.
      void
      modal_damping(Session &s, Words &w, const bool in_tangent)
      {
        const std::string name = w.name;
        std::vector<double> factors;
        while (!w.done())
          factors.push_back(w.real("a damping factor"));
        if (factors.empty())
          throw ScriptError(name + " ?factor - not enough arguments to command");
        for (const double zeta : factors)
          if (!std::isfinite(zeta))
            throw ScriptError(name + ": a damping factor is not finite");
        const std::size_t n_modes = s.domain.modes.eigenvalues.size();
        if (n_modes == 0)
          s.warnings << "WARNING - " << name
                     << " - eigen command needs to be called first - NO MODAL DAMPING APPLIED\n";
        if (factors.size() != 1 && factors.size() < n_modes)
          s.warnings << "WARNING " << name
                     << " - fewer damping factors than modes were specified\n"
                     << std::string(name.size() + 9, ' ')
                     << "- zero damping will be applied to un-specified modes\n";
        if (factors.size() > n_modes && n_modes > 0)
          s.warnings << "WARNING " << name
                     << " - more damping factors than modes were specifed\n"
                     << std::string(name.size() + 9, ' ')
                     << "- ignoring additional damping factors\n";
        std::vector<double> zeta(n_modes, factors.size() == 1 ? factors[0] : 0.0);
        for (std::size_t i = 0; factors.size() > 1 && i < std::min(n_modes, factors.size()); ++i)
          zeta[i] = factors[i];
        s.domain.modal_damping            = zeta;
        s.domain.modal_damping_in_tangent = in_tangent;
        ++s.domain.modal_stamp;
      }

      /// nodeDisp/nodeVel/nodeAccel/nodeReaction/nodeCoord: one DOF's value
      /// (1-based) or the whole node's.
      void
      node_values(Words &w, const std::vector<double> &values, const char *what)
      {
        if (w.done())
          return set_result(w.interp, values);
        const int k = w.integer(what);
        check_done(w);
        if (k <= 0) // OpenSees: the whole node
          return set_result(w.interp, values);
        if (k > static_cast<int>(values.size()))
          throw ScriptError(std::string(what) + " " + std::to_string(k) + " is not one of 1 to " +
                            std::to_string(values.size()));
        set_result(w.interp, values[k - 1]);
      }

      void
      node_response(Session &s, Words &w, std::vector<double> opensees::Node::*response)
      {
        const opensees::Node &n = s.domain.node(w.integer("the node's tag"));
        node_values(w, n.*response, "DOF");
      }

      void
      node_reaction(Session &s, Words &w)
      {
        const opensees::Node &n  = s.domain.node(w.integer("the node's tag"));
        const auto            it = s.reactions.find(n.tag);
        node_values(w, it == s.reactions.end() ? std::vector<double>(n.disp.size(), 0.0) : it->second,
                    "DOF");
      }

      /// reactions <-dynamic|-rayleigh> (OpenSees's calculateNodalReactions:
      /// -incInertia, -dynamical, -Dynamic and -dynamic include the inertia
      /// and damping forces, -rayleigh gives the Rayleigh damping forces alone;
      /// with more than one word the static reactions).
      void
      reactions(Session &s, Words &w)
      {
        using Flag = opensees::Domain::ReactionFlag;
        Flag flag  = Flag::resisting;
        if (w.left() > 1) // OpenSees reads an option only when it is the one word
          {
            s.warnings << "WARNING reactions: " << w.left()
                       << " options given; the static reactions computed, as OpenSees 3.8\n";
            while (!w.done())
              w.word("an option");
          }
        else if (!w.done())
          {
            const std::string option = w.word("the option");
            if (option == "-incInertia" || option == "-dynamical" || option == "-Dynamic" ||
                option == "-dynamic")
              flag = Flag::dynamic;
            else if (option == "-rayleigh")
              flag = Flag::rayleigh;
            else
              throw ScriptError("option '" + option +
                                "' is not -dynamic (-incInertia, -dynamical, -Dynamic) or -rayleigh");
          }
        check_done(w);
        s.reactions = s.domain.reactions(flag);
      }

      template <typename Map>
      std::vector<int>
      tags_of(const Map &map, Words &w)
      {
        check_done(w);
        std::vector<int> tags;
        for (const auto &entry : map)
          tags.push_back(entry.first);
        return tags;
      }

      const opensees::Element &
      element_of(Session &s, Words &w)
      {
        const int  tag = w.integer("the element's tag");
        const auto it  = s.domain.elements.find(tag);
        if (it == s.domain.elements.end())
          throw ScriptError("element " + std::to_string(tag) + " does not exist");
        return *it->second;
      }

      /// eleForce tag <dof>: the global resisting force, all or one (1-based).
      void
      element_force(Session &s, Words &w)
      {
        const opensees::Element &e = element_of(s, w);
        node_values(w, s.domain.element_response(e, {"force"}), "DOF");
      }

      void
      wipe_analysis(Session &s, Words &w)
      {
        check_done(w);
        add_counts(s);
        s.analysis.reset();
        s.options  = opensees::AnalysisOptions();
        s.has_test = s.has_algorithm = false;
        s.has_static_integrator = s.has_transient_integrator = false;
      }
      /// getTime <format>: in a script OpenSees's text, printf's "%f" (six
      /// decimals) or the script's format of one floating conversion; a
      /// float in poundfe.opensees (OpenSeesPy's).
      void
      get_time(Session &s, Words &w)
      {
        const std::string format = w.done() ? "%f" : w.word("the format");
        check_done(w);
        if (s.without_bodies)
          return set_result(w.interp, s.domain.time);
        static const std::regex one_conversion(
          "[^%]*%[-+# 0]*[0-9]{0,3}(\\.[0-9]{1,3})?[eEfFgG][^%]*");
        if (!std::regex_match(format, one_conversion))
          throw ScriptError("format '" + format + "' is not one floating-point conversion");
        char text[512];
        std::snprintf(text, sizeof text, format.c_str(), s.domain.time);
        Tcl_SetObjResult(w.interp, Tcl_NewStringObj(text, -1));
      }

      /// testIter, testNorm: the script's test at its last step (none run
      /// yet: 0 and maxIter zeros). testNorm in a script is OpenSees's text,
      /// each norm as "%35.20e"; a list of floats in poundfe.opensees.
      void
      test_results(Session &s, Words &w, const bool norms)
      {
        check_done(w);
        if (!s.analysis && !s.has_test)
          throw ScriptError("no convergence test");
        if (norms)
          {
            const auto &reached = s.analysis ? s.analysis->test_norms : std::vector<double>();
            const auto  n       = !reached.empty() ?
                                    reached :
                                    std::vector<double>(s.options.test.max_iterations);
            if (s.without_bodies)
              return set_result(w.interp, n);
            std::string text;
            char        number[64];
            for (const double norm : n)
              {
                std::snprintf(number, sizeof number, "%35.20e", norm);
                text += number;
              }
            Tcl_SetObjResult(w.interp, Tcl_NewStringObj(text.c_str(), -1));
          }
        else
          Tcl_SetObjResult(w.interp,
                           Tcl_NewIntObj(s.analysis ? s.analysis->test_iterations : 0));
      }
    } // namespace

    void
    define_analysis_commands(Tcl_Interp *interp, Session &session)
    {
      define(interp, session, "constraints", constraint_handler);
      define(interp, session, "numberer", [](Session &, Words &w) {
        accept_names(w, {"Plain", "RCM", "AMD"});
      });
      // OpenSees's banded and profile systems: LAPACK's banded LU after a
      // Cuthill-McKee numbering; every other one UMFPACK (the same numbers
      // to round-off)
      define(interp, session, "system", [](Session &s, Words &w) {
        const std::string name =
          accept_names(w, {"BandGeneral", "BandGen", "BandSPD", "ProfileSPD", "SparseGeneral",
                           "SparseGEN", "UmfPack", "Umfpack", "FullGeneral", "SparseSYM",
                           "SparseSPD", "Mumps"});
        s.options.banded_system =
          name == "BandGeneral" || name == "BandGen" || name == "BandSPD" || name == "ProfileSPD";
        reconfigure(s);
      });
      define(interp, session, "test", test);
      define(interp, session, "algorithm", algorithm);
      define(interp, session, "integrator", integrator);
      define(interp, session, "analysis", analysis);
      define(interp, session, "analyze", analyze);
      define(interp, session, "eigen", eigen);
      define(interp, session, "modalDamping", [](Session &s, Words &w) { modal_damping(s, w, true); });
      define(interp, session, "modalDampingQ", [](Session &s, Words &w) { modal_damping(s, w, false); });
      define(interp, session, "wipeAnalysis", wipe_analysis);
      define(interp, session, "eleForce", element_force);
      define(interp, session, "eleResponse", [](Session &s, Words &w) {
        const opensees::Element &e = element_of(s, w);
        std::vector<std::string> words;
        while (!w.done())
          words.push_back(w.word("the response"));
        set_result(w.interp, s.domain.element_response(e, words));
      });
      define(interp, session, "testIter",
             [](Session &s, Words &w) { test_results(s, w, false); });
      for (const char *name : {"testNorm", "testNorms"})
        define(interp, session, name, [](Session &s, Words &w) { test_results(s, w, true); });
      // Each process runs the whole script alone; under mpirun, its rank and
      // the job's size as OpenSeesMP says them (1 and 0 launched alone, as
      // OpenSees's sequential interpreter), so that a script can write one
      // file per process.
      define(interp, session, "getNP", [](Session &, Words &w) {
        check_done(w);
        Tcl_SetObjResult(w.interp, Tcl_NewIntObj(launched_size()));
      });
      define(interp, session, "getPID", [](Session &, Words &w) {
        check_done(w);
        Tcl_SetObjResult(w.interp, Tcl_NewIntObj(launched_rank()));
      });
      define(interp, session, "getTime", get_time);
      define(interp, session, "nodeDisp",
             [](Session &s, Words &w) { node_response(s, w, &opensees::Node::disp); });
      define(interp, session, "nodeVel",
             [](Session &s, Words &w) { node_response(s, w, &opensees::Node::vel); });
      define(interp, session, "nodeAccel",
             [](Session &s, Words &w) { node_response(s, w, &opensees::Node::accel); });
      define(interp, session, "nodeCoord",
             [](Session &s, Words &w) { node_response(s, w, &opensees::Node::coordinates); });
      define(interp, session, "nodeReaction", node_reaction);
      define(interp, session, "reactions", reactions);
      define(interp, session, "getNodeTags", [](Session &s, Words &w) {
        set_result(w.interp, tags_of(s.domain.nodes, w));
      });
      define(interp, session, "getEleTags", [](Session &s, Words &w) {
        set_result(w.interp, tags_of(s.domain.elements, w));
      });
    }
  } // namespace opensees_tcl
} // namespace poundfe
