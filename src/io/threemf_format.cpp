//! 3MF reader and writer over lib3mf's C interface, with owned handles.
#include "io/threemf_format.h"

#include <Model/COM/NMR_DLLInterfaces.h>

#include <array>
#include <vector>

#include "core/atomic_output.h"
#include "core/error.h"
#include "io/input_file.h"

namespace fabvdb::io {

namespace {

using namespace NMR;

//! One lib3mf object reference, released when it goes out of scope.
class Handle {
public:
    Handle() = default;
    ~Handle() {
        if (object_) lib3mf_release(object_);
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    PLib3MFBase* get() const { return object_; }
    //! The slot lib3mf writes a new reference to.
    PLib3MFBase** out() { return &object_; }

private:
    PLib3MFBase* object_ = nullptr;
};

//! Row-major 3x4 affine map: p' = A p + t, as lib3mf's MODELTRANSFORM stores it.
using Affine = std::array<std::array<double, 4>, 3>;

constexpr int max_component_depth = 32;

Affine to_affine(const MODELTRANSFORM& transform) {
    Affine affine;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) affine[r][c] = transform.m_fFields[r][c];
    return affine;
}

//! outer ∘ inner: apply `inner` first.
Affine compose(const Affine& outer, const Affine& inner) {
    Affine result{};
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 4; ++c) {
            double sum = c == 3 ? outer[r][3] : 0.0;
            for (int k = 0; k < 3; ++k) sum += outer[r][k] * inner[k][c];
            result[r][c] = sum;
        }
    }
    return result;
}

double millimetres_per_unit(DWORD unit) {
    switch (unit) {
        case MODELUNIT_MICROMETER: return 0.001;
        case MODELUNIT_CENTIMETER: return 10.0;
        case MODELUNIT_INCH: return 25.4;
        case MODELUNIT_FOOT: return 304.8;
        case MODELUNIT_METER: return 1000.0;
        default: return 1.0;
    }
}

std::string last_error(PLib3MFBase* instance) {
    DWORD code = 0;
    LPCSTR message = nullptr;
    if (instance && lib3mf_getlasterror(instance, &code, &message) == LIB3MF_OK && message && *message) return message;
    return "lib3mf error " + std::to_string(code);
}

class ModelReader {
public:
    ModelReader(std::string path, Progress& progress) : path_(std::move(path)), progress_(progress) {}

    Mesh read() {
        readable_file_size(path_);
        Handle model;
        Handle reader;
        if (lib3mf_createmodel(model.out()) != LIB3MF_OK)
            throw Error(FABVDB_ERR_INTERNAL, path_ + ": lib3mf could not create a model");
        check(lib3mf_model_queryreader(model.get(), "3mf", reader.out()), model.get(), "cannot create a 3MF reader");
        if (lib3mf_reader_readfromfileutf8(reader.get(), path_.c_str()) != LIB3MF_OK)
            throw Error(FABVDB_ERR_BAD_INPUT, path_ + ": not a valid 3MF package: " + last_error(reader.get()));
        DWORD unit = MODELUNIT_MILLIMETER;
        check(lib3mf_model_getunit(model.get(), &unit), model.get(), "cannot read the unit");
        const double scale = millimetres_per_unit(unit);
        const Affine to_millimetres{{{scale, 0, 0, 0}, {0, scale, 0, 0}, {0, 0, scale, 0}}};

        Handle items;
        check(lib3mf_model_getbuilditems(model.get(), items.out()), model.get(), "cannot list the build items");
        BOOL has_next = false;
        check(lib3mf_builditemiterator_movenext(items.get(), &has_next), items.get(), "cannot list the build items");
        while (has_next) {
            Handle item;
            Handle object;
            check(lib3mf_builditemiterator_getcurrent(items.get(), item.out()), items.get(), "cannot read a build item");
            check(lib3mf_builditem_getobjectresource(item.get(), object.out()), item.get(),
                  "cannot read a build item's object");
            MODELTRANSFORM transform;
            check(lib3mf_builditem_getobjecttransform(item.get(), &transform), item.get(),
                  "cannot read a build item's transform");
            add_object(model.get(), object.get(), compose(to_millimetres, to_affine(transform)), 0);
            check(lib3mf_builditemiterator_movenext(items.get(), &has_next), items.get(), "cannot list the build items");
        }
        return std::move(mesh_);
    }

private:
    void check(LIB3MFRESULT result, PLib3MFBase* instance, const char* what) const {
        if (result != LIB3MF_OK) throw Error(FABVDB_ERR_BAD_INPUT, path_ + ": " + what + ": " + last_error(instance));
    }

    void add_object(PLib3MFBase* model, PLib3MFBase* object, const Affine& transform, int depth) {
        if (depth > max_component_depth)
            throw Error(FABVDB_ERR_BAD_INPUT, path_ + ": components nested more than " +
                                                  std::to_string(max_component_depth) + " deep");
        progress_.check();
        BOOL is_mesh = false;
        BOOL is_components = false;
        check(lib3mf_object_ismeshobject(object, &is_mesh), object, "cannot read an object");
        check(lib3mf_object_iscomponentsobject(object, &is_components), object, "cannot read an object");
        if (is_mesh) add_mesh(object, transform);
        if (!is_components) return;
        DWORD count = 0;
        check(lib3mf_componentsobject_getcomponentcount(object, &count), object, "cannot read a components object");
        for (DWORD i = 0; i < count; ++i) {
            Handle component;
            Handle child;
            check(lib3mf_componentsobject_getcomponent(object, i, component.out()), object, "cannot read a component");
            check(lib3mf_component_getobjectresource(component.get(), child.out()), component.get(),
                  "cannot read a component's object");
            MODELTRANSFORM local;
            check(lib3mf_component_gettransform(component.get(), &local), component.get(),
                  "cannot read a component's transform");
            add_object(model, child.get(), compose(transform, to_affine(local)), depth + 1);
        }
    }

    void add_mesh(PLib3MFBase* object, const Affine& transform) {
        DWORD vertex_count = 0;
        DWORD triangle_count = 0;
        check(lib3mf_meshobject_getvertexcount(object, &vertex_count), object, "cannot read a mesh");
        check(lib3mf_meshobject_gettrianglecount(object, &triangle_count), object, "cannot read a mesh");
        std::vector<MODELMESHVERTEX> vertices(vertex_count);
        std::vector<MODELMESHTRIANGLE> triangles(triangle_count);
        if (vertex_count)
            check(lib3mf_meshobject_getvertices(object, vertices.data(), vertex_count, nullptr), object,
                  "cannot read a mesh's vertices");
        if (triangle_count)
            check(lib3mf_meshobject_gettriangleindices(object, triangles.data(), triangle_count, nullptr), object,
                  "cannot read a mesh's triangles");
        const uint64_t base = mesh_.vertices.size();
        if (base + vertex_count > UINT32_MAX) throw Error(FABVDB_ERR_BAD_INPUT, path_ + ": too many vertices");
        for (const MODELMESHVERTEX& v : vertices) {
            Vec3 p;
            for (int r = 0; r < 3; ++r)
                p[r] = transform[r][0] * v.m_fPosition[0] + transform[r][1] * v.m_fPosition[1] +
                       transform[r][2] * v.m_fPosition[2] + transform[r][3];
            mesh_.vertices.push_back(p);
        }
        for (const MODELMESHTRIANGLE& t : triangles) {
            Triangle triangle;
            for (int k = 0; k < 3; ++k) {
                if (t.m_nIndices[k] >= vertex_count)
                    throw Error(FABVDB_ERR_BAD_INPUT, path_ + ": a triangle uses vertex " +
                                                          std::to_string(t.m_nIndices[k]) + " of a mesh with " +
                                                          std::to_string(vertex_count) + " vertices");
                triangle[k] = static_cast<uint32_t>(base + t.m_nIndices[k]);
            }
            mesh_.triangles.push_back(triangle);
        }
    }

    std::string path_;
    Progress& progress_;
    Mesh mesh_;
};

}  // namespace

Mesh read_3mf(const std::string& path, Progress& progress) { return ModelReader(path, progress).read(); }

void write_3mf(const Mesh& mesh, const std::string& path) {
    if (mesh.triangles.empty()) throw Error(FABVDB_ERR_BAD_INPUT, path + ": a 3MF mesh needs triangles");
    if (mesh.vertices.size() > UINT32_MAX || mesh.triangles.size() > UINT32_MAX)
        throw Error(FABVDB_ERR_BAD_INPUT, path + ": too large for a 3MF mesh object");
    auto check = [&path](LIB3MFRESULT result, PLib3MFBase* instance, const char* what) {
        if (result != LIB3MF_OK) throw Error(FABVDB_ERR_IO, path + ": " + what + ": " + last_error(instance));
    };
    Handle model;
    Handle object;
    Handle item;
    Handle writer;
    if (lib3mf_createmodel(model.out()) != LIB3MF_OK)
        throw Error(FABVDB_ERR_INTERNAL, path + ": lib3mf could not create a model");
    check(lib3mf_model_setunit(model.get(), MODELUNIT_MILLIMETER), model.get(), "cannot set the unit");
    check(lib3mf_model_addmeshobject(model.get(), object.out()), model.get(), "cannot add a mesh object");
    std::vector<MODELMESHVERTEX> vertices(mesh.vertices.size());
    for (size_t i = 0; i < vertices.size(); ++i)
        for (int k = 0; k < 3; ++k) vertices[i].m_fPosition[k] = static_cast<FLOAT>(mesh.vertices[i][k]);
    std::vector<MODELMESHTRIANGLE> triangles(mesh.triangles.size());
    for (size_t i = 0; i < triangles.size(); ++i)
        for (int k = 0; k < 3; ++k) triangles[i].m_nIndices[k] = mesh.triangles[i][k];
    check(lib3mf_meshobject_setgeometry(object.get(), vertices.data(), static_cast<DWORD>(vertices.size()),
                                        triangles.data(), static_cast<DWORD>(triangles.size())),
          object.get(), "lib3mf rejected the mesh");
    check(lib3mf_model_addbuilditem(model.get(), object.get(), nullptr, item.out()), model.get(),
          "cannot add a build item");
    check(lib3mf_model_querywriter(model.get(), "3mf", writer.out()), model.get(), "cannot create a 3MF writer");
    AtomicOutput output(path);
    check(lib3mf_writer_writetofileutf8(writer.get(), output.temp_path().c_str()), writer.get(), "write failed");
    output.commit();
}

}  // namespace fabvdb::io
