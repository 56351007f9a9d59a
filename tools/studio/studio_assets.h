/* studio_assets.h — the files of the studio's page, embedded into `fabvdb`
 * at build time (cmake/embed_studio.cmake writes studio_assets.c from
 * studio/ and the pinned three.js and three-mesh-bvh modules in
 * studio/node_modules), so the command needs neither network nor an
 * install folder to serve its page. */
#ifndef FABVDB_STUDIO_ASSETS_H
#define FABVDB_STUDIO_ASSETS_H

#include <stddef.h>

typedef struct studio_asset {
    const char* path; /* relative to the page's folder: "index.html", "vendor/three.module.js" */
    const char* mime;
    const unsigned char* data;
    const unsigned char* end; /* one past the last byte */
} studio_asset;

extern const studio_asset studio_assets[];
extern const size_t studio_asset_count;
/* 0 when studio/node_modules was missing at build time (the page cannot run). */
extern const int studio_assets_complete;

#endif
