#include "compare/vtk_xml_index.hpp"

#include <vtkNew.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <string_view>

#include "core/error.hpp"
#include "io/vtk_error_capture.hpp"

namespace mrsim {
namespace {

InputError index_error(const std::filesystem::path& file, const std::string& message) {
  return InputError(file.string() + ": " + message);
}

XmlAttributes attributes_of(vtkXMLDataElement* element) {
  XmlAttributes attributes;
  for (int i = 0; i < element->GetNumberOfAttributes(); ++i) {
    attributes[element->GetAttributeName(i)] = element->GetAttributeValue(i);
  }
  return attributes;
}

vtkXMLDataElement* section_of(vtkXMLDataElement* root, const std::string& type,
                              const std::filesystem::path& file) {
  const char* declared = root->GetAttribute("type");
  if (std::string_view(root->GetName()) != "VTKFile" || declared == nullptr || type != declared) {
    throw index_error(file, "not a VTK " + type + " file");
  }
  vtkXMLDataElement* section = root->FindNestedElementWithName(type.c_str());
  if (section == nullptr) throw index_error(file, "no <" + type + "> element");
  return section;
}

}  // namespace

std::vector<XmlAttributes> read_dataset_entries(const std::filesystem::path& file,
                                                const std::string& type) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) throw index_error(file, "file not found");
  VtkErrorCapture capture;  // the XML parser reports through vtkErrorMacro
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(file.c_str());
  if (parser->Parse() == 0 || capture.any() || parser->GetRootElement() == nullptr) {
    throw index_error(
        file, "not well-formed XML" + (capture.any() ? ": " + capture.summary() : std::string()));
  }
  vtkXMLDataElement* section = section_of(parser->GetRootElement(), type, file);
  std::vector<XmlAttributes> entries;
  for (int i = 0; i < section->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* child = section->GetNestedElement(i);
    if (std::string_view(child->GetName()) != "DataSet") {
      throw index_error(
          file, std::string("unsupported element <") + child->GetName() + "> (nested blocks?)");
    }
    entries.push_back(attributes_of(child));
  }
  return entries;
}

}  // namespace mrsim
