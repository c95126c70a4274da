#!/usr/bin/env bash
# The install check: installs a build into a staging folder (DESTDIR), checks every file a desktop user
# gets, validates the desktop entry, the MIME type and the AppStream metainfo, renders the man page, runs
# the staged binary on a staged example project, and builds the Debian package and checks what it holds.
# Usage: check-install.sh BUILD_DIR WORK_DIR
set -euo pipefail
build=$(realpath "$1")
work=$(realpath -m "$2")
rm -rf "$work"
mkdir -p "$work"
stage=$work/stage
fail() {
    echo "check-install: $*" >&2
    exit 1
}

DESTDIR=$stage cmake --install "$build" --prefix /usr >"$work/install.log"
id=org.speculum.Speculum
for f in bin/speculum \
    share/applications/$id.desktop \
    share/icons/hicolor/scalable/apps/$id.svg \
    share/mime/packages/$id.xml \
    share/metainfo/$id.metainfo.xml \
    share/man/man1/speculum.1 \
    share/speculum/scenes/teapot.speculum.json share/speculum/scenes/mirrors.speculum.json \
    share/speculum/scenes/chrome.speculum.json share/speculum/scenes/models.speculum.json \
    share/speculum/scenes/textures/marble.png share/speculum/models/toyset.glb; do
    [ -s "$stage/usr/$f" ] || fail "the install lacks usr/$f"
done
[ -x "$stage/usr/bin/speculum" ] || fail "usr/bin/speculum is not executable"

desktop-file-validate "$stage/usr/share/applications/$id.desktop" || fail "the desktop entry does not validate"
grep -q '^Exec=speculum %f$' "$stage/usr/share/applications/$id.desktop" || fail "the desktop entry's Exec"
appstreamcli validate --no-net "$stage/usr/share/metainfo/$id.metainfo.xml" >"$work/appstream.log" ||
    { cat "$work/appstream.log" >&2; fail "the metainfo does not validate"; }
# The MIME database built from the staged package file maps *.speculum.json to the project type.
update-mime-database "$stage/usr/share/mime"
grep -q 'application/x-speculum-project:\*\.speculum\.json' "$stage/usr/share/mime/globs2" ||
    fail "the MIME database has no glob for *.speculum.json"
grep -q 'SVG' <(file "$stage/usr/share/icons/hicolor/scalable/apps/$id.svg") || fail "the icon is not an SVG"
man -l "$stage/usr/share/man/man1/speculum.1" 2>/dev/null | grep -q 'speculum - scene editor for mirrors' ||
    fail "the man page does not render"

# The staged binary runs, headless, on a staged example (its model and textures found beside it).
"$stage/usr/bin/speculum" --version | grep -q '^speculum ' || fail "speculum --version"
for demo in teapot models; do
    "$stage/usr/bin/speculum" render "$stage/usr/share/speculum/scenes/$demo.speculum.json" \
        -o "$work/$demo.png" --size 64x36 >"$work/$demo.log" 2>&1 || { cat "$work/$demo.log" >&2; fail "render $demo"; }
    [ -s "$work/$demo.png" ] || fail "render $demo wrote nothing"
done

# The Debian package, from the same install rules; dpkg-shlibdeps names the libraries' packages.
(cd "$work" && cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/deb" >"$work/cpack.log") ||
    { cat "$work/cpack.log" >&2; fail "cpack -G DEB"; }
deb=$(ls "$work"/deb/speculum_*.deb 2>/dev/null | head -n 1)
[ -n "$deb" ] || fail "no .deb was built"
dpkg-deb -c "$deb" >"$work/deb-contents.txt"
for f in ./usr/bin/speculum ./usr/share/applications/$id.desktop ./usr/share/metainfo/$id.metainfo.xml \
    ./usr/share/speculum/scenes/teapot.speculum.json ./usr/share/man/man1/speculum.1; do
    grep -q " $f\$" "$work/deb-contents.txt" || fail "the package lacks $f"
done
depends=$(dpkg-deb -f "$deb" Depends)
for lib in libqt6widgets6 libopenimageio2.4 libassimp5 libembree3 libegl1 qt6-qpa-plugins; do
    [[ $depends == *"$lib"* ]] || fail "the package's Depends lacks $lib: $depends"
done
echo "check-install: installed, validated, ran and packaged ($(basename "$deb"))"
