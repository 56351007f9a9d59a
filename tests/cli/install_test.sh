# install_test.sh — `cmake --install` gives a usable package: a program outside
# the tree builds and runs against it through find_package(fabvdb) and through
# pkg-config, the installed `fabvdb` command runs, and `man fabvdb` finds its
# installed man page.
source "$(dirname "$0")/lib.sh"
BUILD="$(dirname "$FABVDB")"
PREFIX="$WORK/prefix"

expect_exit 0 cmake --install "$BUILD" --prefix "$PREFIX"
expect_exit 0 test -f "$PREFIX/include/fabvdb.h"
expect_exit 0 test -f "$PREFIX/include/fabvdb_version.h"
libdir="$(dirname "$(find "$PREFIX" -name 'libfabvdb.so' | head -n 1)")"
expect_exit 0 cmake -S "$SOURCE/tests/install" -B "$WORK/consumer" -G Ninja -DCMAKE_PREFIX_PATH="$PREFIX"
expect_exit 0 cmake --build "$WORK/consumer"
expect_exit 0 env LD_LIBRARY_PATH="$libdir" "$WORK/consumer/consumer"
expect_match "$STDOUT" 'ok, 4 triangles'

expect_exit 0 env PKG_CONFIG_PATH="$libdir/pkgconfig" pkg-config --cflags --libs fabvdb
flags="$STDOUT"
expect_exit 0 cc "$SOURCE/tests/install/consumer.c" -o "$WORK/consumer_pc" $flags
expect_exit 0 env LD_LIBRARY_PATH="$libdir" "$WORK/consumer_pc"
expect_exit 0 "$PREFIX/bin/fabvdb" --version
expect_exit 0 test -f "$PREFIX/share/man/man1/fabvdb.1"
expect_exit 0 env MANPATH="$PREFIX/share/man" MANWIDTH=100 man -P cat fabvdb
expect_match "$STDOUT" 'fabvdb drain'
expect_match "$STDOUT" 'EXIT STATUS'
finish
