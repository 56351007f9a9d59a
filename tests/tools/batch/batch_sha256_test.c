/* batch_sha256_test.c — tools/batch/batch_sha256.c against FIPS 180-4's
 * examples ("abc", the 448-bit message, a million 'a's: one 64 KiB read
 * after another) and the empty file; a missing file is -1. */
#define _GNU_SOURCE /* mkdtemp, nftw */
#include "batch/batch_sha256.h"
#include "capi/check.h"
#include "tools/temp_folder.h"

static void check_hash(const char* folder, const char* text, const char* wanted) {
    char path[4096], hex[BATCH_SHA256_HEX_LENGTH + 1];
    CHECK(temp_write(temp_path(path, folder, "data"), text) == 0);
    CHECK(batch_sha256_file(path, hex) == 0 && strcmp(hex, wanted) == 0);
}

int main(void) {
    char folder[4096], path[4096], hex[BATCH_SHA256_HEX_LENGTH + 1];
    CHECK(temp_folder_make(folder) == 0);
    check_hash(folder, "", "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    check_hash(folder, "abc", "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    check_hash(folder, "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq",
               "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
    char* million = malloc(1000001);
    memset(million, 'a', 1000000);
    million[1000000] = 0;
    check_hash(folder, million, "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
    free(million);
    CHECK(batch_sha256_file(temp_path(path, folder, "missing"), hex) == -1);
    temp_folder_remove(folder);
    return check_summary();
}
