// libFuzzer target: the input is the XML of a 3MF model part, packed with a
// fixed content-types part and relationship into a valid zip, so mutations
// reach lib3mf's model parser and our object/component walk instead of
// stopping at the zip layer (what fuzz_3mf mostly exercises).
#include <zip.h>

#include "fuzz_read_mesh.h"

namespace {

const char content_types[] =
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    "<Types xmlns=\"http://schemas.openxmlformats.org/package/2006/content-types\">"
    "<Default Extension=\"rels\" ContentType=\"application/vnd.openxmlformats-package.relationships+xml\"/>"
    "<Default Extension=\"model\" ContentType=\"application/vnd.ms-package.3dmanufacturing-3dmodel+xml\"/>"
    "</Types>";
const char relationships[] =
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    "<Relationships xmlns=\"http://schemas.openxmlformats.org/package/2006/relationships\">"
    "<Relationship Target=\"/3D/3dmodel.model\" Id=\"rel0\" "
    "Type=\"http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel\"/></Relationships>";

bool add_part(zip_t* archive, const char* name, const void* data, size_t size) {
    zip_source_t* source = zip_source_buffer(archive, data, size, 0);
    if (!source) return false;
    if (zip_file_add(archive, name, source, ZIP_FL_OVERWRITE) < 0) {
        zip_source_free(source);
        return false;
    }
    return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string path = std::string(std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "/tmp") +
                                    "/fabvdb-fuzz-model-" + std::to_string(getpid()) + ".zip";
    int error = 0;
    zip_t* archive = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
    if (!archive) std::abort();
    if (!add_part(archive, "[Content_Types].xml", content_types, sizeof content_types - 1) ||
        !add_part(archive, "_rels/.rels", relationships, sizeof relationships - 1) ||
        !add_part(archive, "3D/3dmodel.model", data, size) || zip_close(archive) != 0)
        std::abort();
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) std::abort();
    std::string package;
    char buffer[1 << 14];
    for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, file)) > 0;) package.append(buffer, n);
    std::fclose(file);
    std::remove(path.c_str());
    return fuzz_read_mesh(reinterpret_cast<const uint8_t*>(package.data()), package.size(), "3mf");
}
