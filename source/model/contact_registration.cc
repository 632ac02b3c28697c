// The parameters of the gaps and the contact (model/parameter_registry.h),
// all in nonlinear elements only:
//   Model/Separations[i]               gap between buildings i and i+1
//   Contact/Barriers/gap[i]            the gap of barrier i (a bumper no thicker)
//   Contact/Stiffness, Contact/Damping the contact law of every gap
//   Contact/Coefficient of restitution the contact damping as the builder fits it
//                                      (formula or calibration)
//   Bumpers/Stiffness, Bumpers/Thickness
//                                      the bumper of every gap (t at most the
//                                      smallest gap)
// A contact damping fitted to the restitution follows k, e and the gaps'
// effective masses (refit_contact_damping); a bumper is checked against
// the gaps once every value is set (model/building_links.cc,
// model/link_parameters.cc check the same).
#include <poundfe/base/numbers.h>
#include <poundfe/laws/contact_law.h>
#include <poundfe/model/parameter_registry.h>

#include <algorithm>

namespace poundfe
{
  void
  refit_contact_damping(const ModelParameter &, Model &model, const ModelInputs *inputs)
  {
    if (!inputs)
      return;
    const ContactParameters &contact = inputs->contact;
    if (contact_law_is_damped(contact.law) && contact.damping_from != ContactDampingFrom::given)
      model.contact.damping = contact_law_damping(contact, model.contact);
  }
} // namespace poundfe

namespace poundfe::contact_registration
{
  namespace
  {
    const double infinity = std::numeric_limits<double>::infinity();

    /// Indices in model.gaps of the gaps between building b and b + 1 (not barriers).
    std::vector<unsigned int>
    gaps_after(const Model &model, const unsigned int b)
    {
      std::vector<unsigned int> result;
      for (unsigned int g = 0; g < model.gaps.size(); ++g)
        {
          const Gap &gap = model.gaps[g];
          if (gap.nodes[0] >= 0 && gap.nodes[1] >= 0 && gap.buildings[0] == b)
            result.push_back(g);
        }
      return result;
    }

    /// Indices in model.gaps of the Contact/Barriers entries `entry` names
    /// (all: -1, or one): the gaps with a barrier side, in the order listed
    /// (model_builder.cc adds them so, after the gaps between buildings).
    std::vector<unsigned int>
    named_barriers(const int entry, const Model &model)
    {
      std::vector<unsigned int> all;
      for (unsigned int g = 0; g < model.gaps.size(); ++g)
        if (model.gaps[g].nodes[0] < 0 || model.gaps[g].nodes[1] < 0)
          all.push_back(g);
      return entry < 0 || all.empty() ? all : std::vector<unsigned int>{all.at(entry)};
    }

    /// The bumper no thicker than any gap (nor, a table bumper, than its
    /// table: its force beyond is not given), as the builder and the input
    /// check it.
    void
    require_bumper_fits(const ModelParameter &, Model &model, const ModelInputs *)
    {
      const BumperParameters &bumper = model.bumper;
      if (bumper.law == BumperLaw::none)
        return;
      for (const Gap &gap : model.gaps)
        if (bumper.thickness > gap.initial_gap)
          throw std::invalid_argument(
            "the sampled bumper (" + number_text(bumper.thickness) +
            " m) is thicker than the gap " + gap.label + " (" + number_text(gap.initial_gap) +
            " m) (Bumpers/Thickness must not exceed the smallest gap: sample them so, e.g. "
            "bounded or correlated)");
      if (bumper.law == BumperLaw::table && bumper.thickness > bumper.table.back()[0])
        throw std::invalid_argument("the sampled bumper (" + number_text(bumper.thickness) +
                                    " m) is thicker than its Bumpers/Table reaches (" +
                                    number_text(bumper.table.back()[0]) + " m)");
    }

    void
    gaps(ParameterRegistry &registry)
    {
      ParameterRegistration s;
      s.name        = "Model/Separations";
      s.takes_index = true;
      s.range       = {0, true, infinity};
      s.resolve     = [](ModelParameter &p, const Model &model) {
        p.building = p.entry < 0 ? 0 : p.entry; // [i]: the gap after building i
        if (p.building + 1 >= model.buildings.size() || gaps_after(model, p.building).empty())
          refuse_parameter(p, ": no gaps between building " + std::to_string(p.building + 1) +
                                " and " + std::to_string(p.building + 2));
      };
      s.get = [](const ModelParameter &p, const Model &model) {
        return model.gaps[gaps_after(model, p.building).front()].initial_gap;
      };
      s.set = [](const ModelParameter &p, const double value, Model &model, ModelInputs &) {
        for (const unsigned int g : gaps_after(model, p.building))
          model.gaps[g].initial_gap = value;
      };
      s.follow_up = require_bumper_fits;
      // the builder also places the buildings to the right by it: only a
      // pair of shear buildings in a plane has no node that moves with it
      // (a member's length is the difference of its nodes' positions)
      s.built_alike = [](const ModelParameter &, const Model &model) {
        return model.dimension == 2 && model.buildings.size() == 2 &&
               std::all_of(model.buildings.begin(), model.buildings.end(),
                           [](const Building &b) { return b.type == BuildingType::shear; });
      };
      registry.add(s);

      ParameterRegistration b;
      b.name        = "Contact/Barriers/gap";
      b.takes_index = true;
      b.range       = {0, true, infinity};
      b.resolve     = [](ModelParameter &p, const Model &model) {
        const std::size_t n = named_barriers(-1, model).size();
        if (n == 0)
          refuse_parameter(p, ": the model has no Contact/Barriers");
        if (p.entry >= int(n))
          refuse_parameter(p, ": the model has barriers 1.." + std::to_string(n));
      };
      b.get = [](const ModelParameter &p, const Model &model) {
        return model.gaps[named_barriers(p.entry, model).front()].initial_gap;
      };
      b.set = [](const ModelParameter &p, const double value, Model &model, ModelInputs &) {
        for (const unsigned int g : named_barriers(p.entry, model))
          model.gaps[g].initial_gap = value;
      };
      b.follow_up = require_bumper_fits;
      registry.add(b);
      registry.add_explanation([](const ModelParameter &p, const std::string &entry,
                                  const bool of_building, bool, const Model &) {
        if (!of_building && entry.rfind("Contact/Barriers", 0) == 0)
          refuse_parameter(p, ": the barriers' random field is their gap, "
                              "'Contact/Barriers/gap[i]' (building, floor and side place a "
                              "barrier)");
      });
    }

    /// A Contact/ entry of a model with gaps.
    ParameterRegistration
    contact_entry(const std::string &name, const ModelParameter::Range range)
    {
      ParameterRegistration r;
      r.name    = "Contact/" + name;
      r.range   = range;
      r.resolve = [](ModelParameter &p, const Model &model) {
        if (model.gaps.empty())
          refuse_parameter(p, ": the model has no contact (Contact/Law)");
      };
      return r;
    }

    void
    contact(ParameterRegistry &registry)
    {
      for (const bool stiffness : {true, false})
        {
          ParameterRegistration r =
            contact_entry(stiffness ? "Stiffness" : "Damping", {0, !stiffness, infinity});
          r.get = [stiffness](const ModelParameter &, const Model &model) {
            return stiffness ? model.contact.stiffness : model.contact.damping;
          };
          r.set = [stiffness](const ModelParameter &, const double value, Model &model,
                              ModelInputs &) {
            (stiffness ? model.contact.stiffness : model.contact.damping) = value;
          };
          if (stiffness)
            r.follow_up = refit_contact_damping;
          registry.add(r);
        }

      ParameterRegistration e = contact_entry("Coefficient of restitution", {0, false, 1});
      const auto has_gaps = e.resolve;
      e.resolve = [has_gaps](ModelParameter &p, const Model &model) {
        has_gaps(p, model);
        if (!p.inputs)
          refuse_parameter(p, " needs the input the model was built from");
        const ContactParameters &contact = p.inputs->contact;
        if (!contact_law_is_damped(contact.law) ||
            contact.damping_from == ContactDampingFrom::given)
          refuse_parameter(p, ": the contact damping does not come from the restitution (an "
                              "undamped law, or Contact/Damping from = given)");
      };
      e.get = [](const ModelParameter &p, const Model &) { return p.inputs->contact.restitution; };
      e.set = [](const ModelParameter &, const double value, Model &, ModelInputs &inputs) {
        inputs.contact.restitution = value;
      };
      e.follow_up = refit_contact_damping;
      registry.add(e);
    }

    void
    bumpers(ParameterRegistry &registry)
    {
      for (const bool stiffness : {true, false})
        {
          ParameterRegistration r;
          r.name  = stiffness ? "Bumpers/Stiffness" : "Bumpers/Thickness";
          // a bumper of zero thickness is the bare contact
          r.range   = {0, !stiffness, infinity};
          r.resolve = [stiffness](ModelParameter &p, const Model &model) {
            if (model.bumper.law == BumperLaw::none)
              refuse_parameter(p, ": the gaps have no bumper (Bumpers/Law = none)");
            if (stiffness && model.bumper.law == BumperLaw::table)
              refuse_parameter(p, ": a table bumper's force comes from its Bumpers/Table, not "
                                  "a stiffness");
          };
          r.get = [stiffness](const ModelParameter &, const Model &model) {
            return stiffness ? model.bumper.stiffness : model.bumper.thickness;
          };
          r.set = [stiffness](const ModelParameter &, const double value, Model &model,
                              ModelInputs &) {
            (stiffness ? model.bumper.stiffness : model.bumper.thickness) = value;
          };
          r.follow_up = require_bumper_fits;
          registry.add(r);
        }
    }
  } // namespace
} // namespace poundfe::contact_registration

namespace poundfe
{
  void
  register_contact_parameters(ParameterRegistry &registry)
  {
    contact_registration::gaps(registry);
    contact_registration::contact(registry);
    contact_registration::bumpers(registry);
  }
} // namespace poundfe
