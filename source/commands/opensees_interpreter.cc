// The OpenSees commands called one at a time with values (poundfe.opensees,
// OpenSeesPy's calling conventions): a Tcl interpreter holding the same
// command procedures as `poundfe opensees` (define_commands), each call
// evaluated as the one Tcl command whose words are the values (a list is
// one word, as a Tcl list), and the command's result read back by its Tcl
// type: the procedures set a double, an integer or a list of them, so a
// caller gets a real, an integer or a list without parsing text.
#include <poundfe/commands/opensees_interpreter.h>

#include "opensees_tcl.h"

#include <cstring>
#include <thread>

namespace poundfe
{
  namespace
  {
    using opensees_tcl::Session;

    /// A new Tcl object of `value` (reference count 0).
    Tcl_Obj *
    tcl_object_of(const OpenSeesValue &value)
    {
      using Kind = OpenSeesValue::Kind;
      switch (value.kind)
        {
          case Kind::integer:
            return Tcl_NewWideIntObj(value.integer);
          case Kind::real:
            return Tcl_NewDoubleObj(value.real);
          case Kind::text:
            return Tcl_NewStringObj(value.text.c_str(), value.text.size());
          case Kind::list:
            {
              Tcl_Obj *list = Tcl_NewListObj(0, nullptr);
              for (const OpenSeesValue &item : value.items)
                Tcl_ListObjAppendElement(nullptr, list, tcl_object_of(item));
              return list;
            }
          case Kind::none:
            break;
        }
      return Tcl_NewObj();
    }

    bool
    has_type(Tcl_Obj *object, const char *name)
    {
      return object->typePtr && std::strcmp(object->typePtr->name, name) == 0;
    }

    /// The value of a command's result: the procedures' set_result makes a
    /// "double", an "int" or a "list" object; an empty result is nothing,
    /// any other text a text.
    OpenSeesValue
    value_of(Tcl_Obj *object)
    {
      OpenSeesValue value;
      using Kind = OpenSeesValue::Kind;
      if (has_type(object, "list"))
        {
          int       n = 0;
          Tcl_Obj **items;
          Tcl_ListObjGetElements(nullptr, object, &n, &items);
          value.kind = Kind::list;
          for (int i = 0; i < n; ++i)
            value.items.push_back(value_of(items[i]));
        }
      else if (has_type(object, "double"))
        {
          value.kind = Kind::real;
          Tcl_GetDoubleFromObj(nullptr, object, &value.real);
        }
      else if (has_type(object, "int") || has_type(object, "wideInt"))
        {
          Tcl_WideInt integer = 0;
          Tcl_GetWideIntFromObj(nullptr, object, &integer);
          value.kind    = Kind::integer;
          value.integer = integer;
        }
      else if (int length = 0; Tcl_GetStringFromObj(object, &length), length > 0)
        {
          value.kind = Kind::text;
          value.text = Tcl_GetString(object);
        }
      return value;
    }

    /// Commands of a script only: `exit` ends a script (poundfe::'s
    /// commands are poundfe.opensees.poundfe's functions).
    bool
    script_only(const std::string &name)
    {
      return name == "exit" || (name.find("::") != std::string::npos &&
                                name.compare(0, 9, "poundfe::") != 0);
    }

    /// The commands that fill an open Fiber section.
    bool
    fills_section(const std::string &name)
    {
      return name == "patch" || name == "layer" || name == "fiber";
    }
  } // namespace

  struct OpenSeesInterpreter::Implementation
  {
    explicit Implementation(std::ostream &warnings)
      : session(warnings)
    {
      Tcl_FindExecutable(nullptr);
      interp = Tcl_CreateInterp();
      if (Tcl_Init(interp) != TCL_OK)
        {
          const std::string message = Tcl_GetStringResult(interp);
          Tcl_DeleteInterp(interp);
          throw OpenSeesCommandError("", "Tcl could not start: " + message);
        }
      session.without_bodies = true;
      opensees_tcl::define_commands(interp, session);
    }
    ~Implementation()
    {
      session.finish_recorders();
      Tcl_DeleteInterp(interp);
    }
    Session               session;
    Tcl_Interp           *interp = nullptr;
    const std::thread::id thread = std::this_thread::get_id();
  };

  OpenSeesInterpreter::OpenSeesInterpreter(std::ostream &warnings)
    : implementation(std::make_unique<Implementation>(warnings))
  {}

  OpenSeesInterpreter::~OpenSeesInterpreter() = default;

  std::vector<std::pair<std::string, bool>>
  OpenSeesInterpreter::commands() const
  {
    std::vector<std::pair<std::string, bool>> list;
    for (const auto &[name, supported] : implementation->session.commands)
      if (!script_only(name))
        list.emplace_back(name, supported);
    return list;
  }

  OpenSeesValue
  OpenSeesInterpreter::call(const std::string &name, const std::vector<OpenSeesValue> &arguments)
  {
    Implementation &i = *implementation;
    if (std::this_thread::get_id() != i.thread)
      throw OpenSeesCommandError(name, name + ": called from a thread other than the one of "
                                              "the first command (Tcl's interpreter is bound "
                                              "to its thread)");
    const auto command = i.session.commands.find(name);
    if (command == i.session.commands.end() || script_only(name))
      throw OpenSeesCommandError(name, name + ": not an OpenSees command");
    if (!fills_section(name) && name != "wipe")
      try
        {
          opensees_tcl::close_open_section(i.session);
        }
      catch (const std::exception &e)
        {
          throw OpenSeesCommandError(name, std::string("section: ") + e.what());
        }
    std::vector<Tcl_Obj *> words{Tcl_NewStringObj(name.c_str(), name.size())};
    for (const OpenSeesValue &argument : arguments)
      words.push_back(tcl_object_of(argument));
    for (Tcl_Obj *word : words)
      Tcl_IncrRefCount(word);
    const int code = Tcl_EvalObjv(i.interp, words.size(), words.data(), TCL_EVAL_GLOBAL);
    for (Tcl_Obj *word : words)
      Tcl_DecrRefCount(word);
    if (code != TCL_OK) // "name: ..." always (a script's message may start with the name alone)
      {
        const std::string message = Tcl_GetStringResult(i.interp);
        throw OpenSeesCommandError(name, message.rfind(name + ": ", 0) == 0 ?
                                           message :
                                           name + ": " + message);
      }
    OpenSeesValue result = value_of(Tcl_GetObjResult(i.interp));
    Tcl_ResetResult(i.interp);
    return result;
  }

  void
  OpenSeesInterpreter::finish_recorders()
  {
    implementation->session.finish_recorders();
  }
} // namespace poundfe
