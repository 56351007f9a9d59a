/* consumer.c — a program outside the fabvdb tree, built against an installed
 * fabvdb by the install test (CMake package and pkg-config). */
#include <fabvdb.h>
#include <stdio.h>

int main(void) {
    fabvdb_ctx* ctx = NULL;
    if (fabvdb_ctx_new(&ctx) != FABVDB_OK) return 1;
    const double vertices[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const uint32_t triangles[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    fabvdb_mesh* mesh = NULL;
    fabvdb_status status = fabvdb_mesh_new(ctx, vertices, 4, triangles, 4, &mesh);
    printf("fabvdb %s: %s, %zu triangles\n", fabvdb_version_string(), fabvdb_status_string(status),
           fabvdb_mesh_triangle_count(mesh));
    fabvdb_mesh_free(mesh);
    fabvdb_ctx_free(ctx);
    return status == FABVDB_OK && fabvdb_version_number() == FABVDB_VERSION_NUMBER ? 0 : 1;
}
