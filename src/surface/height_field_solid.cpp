//! The solid between two height fields over grid cells (see height_field_solid.h).
#include "surface/height_field_solid.h"

#include "core/error.h"

namespace fabvdb::surface {

size_t join_corner_contacts(const HeightGrid& grid, std::vector<char>& cells) {
    if (cells.size() != size_t(grid.nx) * size_t(grid.ny))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "join corner contacts: sizes do not match the grid");
    auto cell = [&](int i, int j) { return size_t(j) * size_t(grid.nx) + size_t(i); };
    size_t added = 0;
    // A cell added can make a new corner contact only with cells beside it,
    // so passes repeat until one adds nothing.
    for (size_t added_in_pass = 1; added_in_pass > 0;) {
        added_in_pass = 0;
        for (int j = 0; j + 1 < grid.ny; ++j)
            for (int i = 0; i + 1 < grid.nx; ++i) {
                const bool a = cells[cell(i, j)], b = cells[cell(i + 1, j)], c = cells[cell(i, j + 1)],
                           d = cells[cell(i + 1, j + 1)];
                if (a && d && !b && !c) {
                    cells[cell(i + 1, j)] = 1;
                    ++added_in_pass;
                } else if (b && c && !a && !d) {
                    cells[cell(i, j)] = 1;
                    ++added_in_pass;
                }
            }
        added += added_in_pass;
    }
    return added;
}

Mesh height_field_solid(const HeightGrid& grid, const std::vector<char>& cells, const std::vector<double>& lower,
                        const std::vector<double>& upper) {
    const size_t vertex_count = size_t(grid.nx + 1) * size_t(grid.ny + 1);
    if (cells.size() != size_t(grid.nx) * size_t(grid.ny) || lower.size() != vertex_count ||
        upper.size() != vertex_count)
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "height field solid: sizes do not match the grid");
    auto marked = [&](int i, int j) {
        return i >= 0 && j >= 0 && i < grid.nx && j < grid.ny && cells[size_t(j) * size_t(grid.nx) + size_t(i)];
    };
    auto vertex_index = [&](int i, int j) { return size_t(j) * size_t(grid.nx + 1) + size_t(i); };
    for (int j = 0; j <= grid.ny; ++j)
        for (int i = 0; i <= grid.nx; ++i) {
            const bool a = marked(i - 1, j - 1), b = marked(i, j - 1), c = marked(i - 1, j), d = marked(i, j);
            if ((a && d && !b && !c) || (b && c && !a && !d))
                throw Error(FABVDB_ERR_INVALID_ARGUMENT, "height field solid: cells touch only at a corner");
            if ((a || b || c || d) && !(upper[vertex_index(i, j)] > lower[vertex_index(i, j)]))
                throw Error(FABVDB_ERR_INVALID_ARGUMENT, "height field solid: upper height not above lower");
        }

    Mesh mesh;
    std::vector<uint32_t> top(vertex_count, UINT32_MAX), bottom(vertex_count, UINT32_MAX);
    auto top_vertex = [&](int i, int j) {
        const size_t v = vertex_index(i, j);
        if (top[v] == UINT32_MAX) {
            top[v] = uint32_t(mesh.vertices.size());
            mesh.vertices.push_back({grid.x(i), grid.y(j), upper[v]});
        }
        return top[v];
    };
    auto bottom_vertex = [&](int i, int j) {
        const size_t v = vertex_index(i, j);
        if (bottom[v] == UINT32_MAX) {
            bottom[v] = uint32_t(mesh.vertices.size());
            mesh.vertices.push_back({grid.x(i), grid.y(j), lower[v]});
        }
        return bottom[v];
    };
    for (int j = 0; j < grid.ny; ++j)
        for (int i = 0; i < grid.nx; ++i) {
            if (!marked(i, j)) continue;
            mesh.triangles.push_back({top_vertex(i, j), top_vertex(i + 1, j), top_vertex(i + 1, j + 1)});
            mesh.triangles.push_back({top_vertex(i, j), top_vertex(i + 1, j + 1), top_vertex(i, j + 1)});
            mesh.triangles.push_back({bottom_vertex(i, j), bottom_vertex(i + 1, j + 1), bottom_vertex(i + 1, j)});
            mesh.triangles.push_back({bottom_vertex(i, j), bottom_vertex(i, j + 1), bottom_vertex(i + 1, j + 1)});
            // The cell's corners counter-clockwise seen from +Z; a wall on each
            // side whose neighbour is not marked, facing out (to the right).
            const int corner[5][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}, {i, j}};
            const int neighbour[4][2] = {{i, j - 1}, {i + 1, j}, {i, j + 1}, {i - 1, j}};
            for (int side = 0; side < 4; ++side) {
                if (marked(neighbour[side][0], neighbour[side][1])) continue;
                const int* a = corner[side];
                const int* b = corner[side + 1];
                const uint32_t bottom_a = bottom_vertex(a[0], a[1]), bottom_b = bottom_vertex(b[0], b[1]);
                const uint32_t top_a = top_vertex(a[0], a[1]), top_b = top_vertex(b[0], b[1]);
                mesh.triangles.push_back({bottom_a, bottom_b, top_b});
                mesh.triangles.push_back({bottom_a, top_b, top_a});
            }
        }
    return mesh;
}

}  // namespace fabvdb::surface
