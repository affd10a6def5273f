#include "brep/step_file.h"

#include <array>
#include <cctype>
#include <mutex>
#include <optional>
#include <string>
#include <utility>

#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <StepShape_AdvancedFace.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TransferBRep.hxx>
#include <TransferBRep_ShapeMapper.hxx>
#include <Transfer_FinderProcess.hxx>
#include <XSControl_TransferWriter.hxx>
#include <XSControl_WorkSession.hxx>

#include "absl/strings/str_cat.h"

namespace meshseg::brep_internal {
namespace {

// Sets an Interface_Static value for the scope's duration.
class ScopedStatic {
 public:
  ScopedStatic(const char* name, const std::string& value) : name_(name) {
    if (const char* old = Interface_Static::CVal(name); old != nullptr) old_ = old;
    Interface_Static::SetCVal(name, value.c_str());
  }
  ~ScopedStatic() {
    if (old_) Interface_Static::SetCVal(name_, old_->c_str());
  }
  ScopedStatic(const ScopedStatic&) = delete;
  ScopedStatic& operator=(const ScopedStatic&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

constexpr std::array<std::pair<const char*, const char*>, 10> kUnits = {{
    {"mm", "MM"}, {"cm", "CM"}, {"m", "M"}, {"km", "KM"}, {"in", "INCH"},
    {"ft", "FT"}, {"mi", "MI"}, {"mil", "MIL"}, {"um", "UM"}, {"uin", "UIN"},
}};

}  // namespace

std::mutex& StepSessionMutex() {
  static std::mutex* mutex = new std::mutex;
  return *mutex;
}

std::string StepUnitName(const std::string& unit) {
  std::string lower = unit;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const auto& [name, step] : kUnits) {
    if (lower == name) return step;
  }
  return "";
}

std::string StepUnitList() {
  std::string list;
  for (const auto& [name, step] : kUnits) absl::StrAppend(&list, list.empty() ? "" : ", ", name);
  return list;
}

absl::Status WriteStepFile(const TopoDS_Shape& shape,
                           const std::function<std::string(const TopoDS_Face&)>& face_name,
                           const std::string& unit, const std::string& product_name,
                           const std::string& path) {
  const std::string step_unit = StepUnitName(unit);
  if (step_unit.empty()) {
    return absl::InvalidArgumentError(
        absl::StrCat("brep: length unit \"", unit, "\" is not one of ", StepUnitList()));
  }
  std::lock_guard<std::mutex> lock(StepSessionMutex());
  // OpenCASCADE's default messenger prints the transfer statistics to
  // stdout; core/ never prints.
  static std::once_flag quiet;
  std::call_once(quiet, [] {
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  });
  STEPControl_Controller::Init();
  // The model's own unit on both sides: coordinates are written unscaled.
  // The session unit is put back afterwards, as readers convert to it.
  const ScopedStatic schema("write.step.schema", "AP214IS");
  const ScopedStatic session_unit("xstep.cascade.unit", step_unit);
  const ScopedStatic write_unit("write.step.unit", step_unit);
  const ScopedStatic product("write.step.product.name", product_name);
  STEPControl_Writer writer;
  if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone) {
    return absl::InternalError(absl::StrCat("brep: STEP transfer of the shape for \"", path,
                                            "\" failed"));
  }
  const Handle(Transfer_FinderProcess) finder = writer.WS()->TransferWriter()->FinderProcess();
  for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
    const TopoDS_Face& face = TopoDS::Face(it.Current());
    const std::string name = face_name(face);
    if (name.empty()) continue;
    Handle(StepShape_AdvancedFace) entity;
    if (finder->FindTypedTransient(TransferBRep::ShapeMapper(finder, face),
                                   STANDARD_TYPE(StepShape_AdvancedFace), entity)) {
      entity->SetName(new TCollection_HAsciiString(name.c_str()));
    }
  }
  if (writer.Write(path.c_str()) != IFSelect_RetDone) {
    return absl::InternalError(absl::StrCat("brep: cannot write \"", path, "\""));
  }
  return absl::OkStatus();
}

absl::StatusOr<ReadBackFacts> ReadBack(const std::string& path, const std::string& unit) {
  TopoDS_Shape shape;
  {
    // The reader converts to the session unit: the file's own, so that the
    // shape is in the model's units.
    std::lock_guard<std::mutex> lock(StepSessionMutex());
    STEPControl_Controller::Init();
    const ScopedStatic session_unit("xstep.cascade.unit", StepUnitName(unit));
    STEPControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone || reader.TransferRoots() == 0) {
      return absl::InternalError(absl::StrCat("brep: cannot read back \"", path, "\""));
    }
    shape = reader.OneShape();
  }
  ReadBackFacts facts;
  facts.valid = BRepCheck_Analyzer(shape).IsValid();
  TopTools_IndexedMapOfShape map;
  TopExp::MapShapes(shape, TopAbs_SOLID, map);
  facts.solids = map.Extent();
  map.Clear();
  TopExp::MapShapes(shape, TopAbs_FACE, map);
  facts.faces = map.Extent();
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  for (int i = 1; i <= edge_faces.Extent(); ++i) {
    const TopoDS_Edge& edge = TopoDS::Edge(edge_faces.FindKey(i));
    const TopTools_ListOfShape& faces = edge_faces(i);
    if (faces.Extent() != 1 || BRep_Tool::Degenerated(edge) ||
        BRep_Tool::IsClosed(edge, TopoDS::Face(faces.First()))) {
      continue;
    }
    ++facts.free_edges;
  }
  for (TopExp_Explorer it(shape, TopAbs_SOLID); it.More(); it.Next()) {
    GProp_GProps props;
    BRepGProp::VolumeProperties(it.Current(), props);
    facts.volume += props.Mass();
  }
  return facts;
}

}  // namespace meshseg::brep_internal
