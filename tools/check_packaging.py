# SPDX-License-Identifier: MIT
"""Checks of the packaging (run by tools/check_packaging, in its venv).

- the library's sources: src/*.c is HYST_CORE_SOURCES of CMakeLists.txt (the
  MEX build, the Zephyr module and library.json take src/*.c);
- library.json (PlatformIO): the fields PlatformIO requires, the version of
  include/hyst/version.h, build.srcDir/includeDir/srcFilter select exactly
  the library's sources and headers, PlatformIO's own manifest schema, and
  the package PlatformIO packs from it;
- zephyr/: module.yml (parsed by PyYAML), Kconfig (parsed by kconfiglib,
  defaults equal to include/hyst/config.h), CMakeLists.txt run with stand-ins
  for Zephyr's functions;
- the CMake install into a prefix other than the configured one: hyst.pc,
  `pkg-config --cflags --libs hyst`, a C program compiled and linked with
  those flags (and refused at init without them: the layout options), the
  docs and the licence under share/doc/hyst, `hyst --version`.

Prints one line per check and "packaging: N passed, M failed".
"""
import fnmatch
import json
import os
import re
import shutil
import subprocess
import sys
import tarfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
WORK = ROOT / "build" / "pkgcheck"
RESULTS = []
INSTALLED = []


def check(name):
    def wrap(fn):
        RESULTS.append((name, fn))
        return fn
    return wrap


def run(cmd, **kw):
    r = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        raise AssertionError(f"{' '.join(map(str, cmd))}: exit {r.returncode}\n"
                             f"{r.stdout[-2000:]}{r.stderr[-2000:]}")
    return r.stdout


def version():
    text = (ROOT / "include/hyst/version.h").read_text()
    parts = [re.search(rf"#define HYST_VERSION_{p} (\d+)", text).group(1)
             for p in ("MAJOR", "MINOR", "PATCH")]
    return ".".join(parts)


def config_default(name):
    text = (ROOT / "include/hyst/config.h").read_text()
    return int(re.search(rf"#ifndef {name}\n#define {name} (\d+)", text).group(1))


def core_sources():
    """HYST_CORE_SOURCES of the root CMakeLists.txt, as file names."""
    text = (ROOT / "CMakeLists.txt").read_text()
    block = re.search(r"set\(HYST_CORE_SOURCES\n(.*?)\)", text, re.S).group(1)
    return sorted(Path(line.strip().split("/")[-1]).name for line in block.split("\n")
                  if line.strip())


def src_filter(src_dir, rules):
    """Files under src_dir that PlatformIO's srcFilter rules select ("+<glob>",
    "-<glob>", applied in order, globs relative to src_dir)."""
    if isinstance(rules, str):
        rules = re.findall(r"[+-]<[^>]*>", rules)
    files = [p.relative_to(src_dir).as_posix() for p in src_dir.rglob("*") if p.is_file()]
    chosen = set()
    for rule in rules:
        sign, pattern = rule[0], rule[2:-1]
        hit = {f for f in files if fnmatch.fnmatch(f, pattern) or f.startswith(pattern + "/")}
        chosen = chosen | hit if sign == "+" else chosen - hit
    return sorted(chosen)


@check("src/*.c is HYST_CORE_SOURCES of CMakeLists.txt")
def _():
    globbed = sorted(p.name for p in (ROOT / "src").glob("*.c"))
    assert globbed == core_sources(), f"src/*.c {globbed} != {core_sources()}"


@check("library.json: required fields, version of version.h")
def _():
    m = json.loads((ROOT / "library.json").read_text())
    for field in ("name", "version", "description", "keywords", "license", "build"):
        assert field in m, f"no field {field}"
    assert re.fullmatch(r"[a-z0-9]+(-[a-z0-9]+)*", m["name"]), m["name"]
    assert m["version"] == version(), f"version {m['version']} != version.h {version()}"
    assert m["license"] == "MIT"
    assert (ROOT / "include" / m["headers"]).is_file(), m["headers"]


@check("library.json: build.srcDir/srcFilter select the library's sources, includeDir its headers")
def _():
    b = json.loads((ROOT / "library.json").read_text())["build"]
    src = ROOT / b["srcDir"]
    assert src.is_dir() and (ROOT / b["includeDir"] / "hyst" / "hyst.h").is_file()
    chosen = src_filter(src, b["srcFilter"])
    assert chosen == core_sources(), f"srcFilter selects {chosen}"


@check("library.json: PlatformIO's manifest schema")
def _():
    from platformio.package.manifest.parser import ManifestParserFactory
    from platformio.package.manifest.schema import ManifestSchema
    offline_spdx()
    parsed = ManifestParserFactory.new_from_file(str(ROOT / "library.json")).as_dict()
    data = ManifestSchema().load_manifest(parsed)
    # (the schema checks the registry's fields; "build" is checked above)
    assert data["name"] == "hyst" and data["version"] == version(), data
    assert data["headers"] == ["hyst/hyst.h"] and data["license"] == "MIT", data


@check("library.json: the package PlatformIO packs (export.include)")
def _():
    from platformio.package.pack import PackagePacker
    offline_spdx()
    out = WORK / "pio"
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    archive = Path(PackagePacker(str(ROOT)).pack(str(out)))
    with tarfile.open(archive) as tar:
        names = set(tar.getnames())
    assert archive.name == f"hyst-{version()}.tar.gz", archive.name
    for want in ("library.json", "LICENSE", "include/hyst/hyst.h", "src/hyst_f32.c",
                 "src/tcm_engine.h", "docs/api.md"):
        assert want in names, f"{want} not in the package"
    for name in names:
        assert not name.startswith(("tests/", "build/", "python/", "matlab/")), name


def offline_spdx():
    """PlatformIO fetches the SPDX licence list from the network to check the
    licence field; the build machines reach package registries only, so the
    one identifier used here is supplied instead."""
    from platformio.package.manifest.schema import ManifestSchema
    ManifestSchema.load_spdx_licenses = staticmethod(
        lambda: {"licenses": [{"licenseId": "MIT"}]})


@check("zephyr/module.yml: name, build.cmake, build.kconfig")
def _():
    import yaml
    m = yaml.safe_load((ROOT / "zephyr" / "module.yml").read_text())
    assert m["name"] == "hyst", m
    assert set(m["build"]) == {"cmake", "kconfig"}, m["build"]
    assert (ROOT / m["build"]["cmake"] / "CMakeLists.txt").is_file(), m["build"]["cmake"]
    assert (ROOT / m["build"]["kconfig"]).is_file(), m["build"]["kconfig"]


@check("zephyr/Kconfig: parses; defaults of include/hyst/config.h")
def _():
    import kconfiglib
    WORK.mkdir(parents=True, exist_ok=True)
    top = WORK / "Kconfig"
    # REQUIRES_FULL_LIBC is Zephyr's (lib/libc/Kconfig)
    top.write_text(f'config REQUIRES_FULL_LIBC\n\tbool\nsource "{ROOT}/zephyr/Kconfig"\n')
    kconf = kconfiglib.Kconfig(str(top), warn_to_stderr=False)
    assert not kconf.warnings, kconf.warnings
    syms = kconf.syms
    syms["HYST"].set_value(2)
    assert syms["REQUIRES_FULL_LIBC"].str_value == "y", "HYST must select REQUIRES_FULL_LIBC"
    for name in ("HYST_MAX_DEGREE", "HYST_INV_KNOTS", "HYST_CODE_BITS"):
        assert int(syms[name].str_value) == config_default(name), \
            f"{name}: Kconfig {syms[name].str_value}, config.h {config_default(name)}"
    assert syms["HYST_F64_AUTO"].str_value == "y"
    syms["HYST_F64_OFF"].set_value(2)
    assert syms["HYST_USE_DOUBLE"].visibility == 0, "HYST_USE_DOUBLE without f64"


@check("zephyr/CMakeLists.txt: the library's sources, include/, layout definitions")
def _():
    WORK.mkdir(parents=True, exist_ok=True)
    log = WORK / "zephyr_calls.txt"
    script = WORK / "zephyr_stub.cmake"
    script.write_text(f"""
set(LOG "{log}")
file(WRITE ${{LOG}} "")
foreach(fn zephyr_library_named zephyr_library_sources zephyr_include_directories
           zephyr_compile_definitions)
    cmake_language(EVAL CODE "function(${{fn}})\\n file(APPEND \\${{LOG}} \\"${{fn}};\\${{ARGN}}\\\\n\\")\\nendfunction()")
endforeach()
set(CONFIG_HYST y)
set(CONFIG_HYST_MAX_DEGREE 5)
set(CONFIG_HYST_INV_KNOTS 16)
set(CONFIG_HYST_CODE_BITS 12)
set(CONFIG_HYST_F64_OFF y)
include("{ROOT}/zephyr/CMakeLists.txt")
""")
    run(["cmake", "-P", str(script)])
    calls = {}
    for line in log.read_text().splitlines():
        fn, *args = line.split(";")
        calls.setdefault(fn, []).extend(args)
    assert calls["zephyr_library_named"] == ["hyst"], calls
    assert sorted(Path(p).name for p in calls["zephyr_library_sources"]) == core_sources()
    assert all(Path(p).is_file() for p in calls["zephyr_library_sources"])
    assert [Path(p).resolve() for p in calls["zephyr_include_directories"]] == [ROOT / "include"]
    assert sorted(calls["zephyr_compile_definitions"]) == sorted(
        ["HYST_MAX_DEGREE=5", "HYST_INV_KNOTS=16", "HYST_CODE_BITS=12", "HYST_ENABLE_F64=0"]), \
        calls["zephyr_compile_definitions"]


PROGRAM = r"""
#include <stdio.h>
#include "hyst/hyst.h"
static const hyst_poly_t f0 = { 3, 0.0, 40.0, { -6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1 } };
HYST_F32_DEFINE(axis, 64);
int main(void)
{
    const int st = HYST_F32_INIT(axis, &f0);
    printf("%d %s %.6f\n", st, HYST_VERSION_STRING, st == HYST_OK ? (double)hyst_f32_step(&axis, 20.0f) : 0.0);
    return 0;
}
"""


def install_prefix():
    """The library configured with a layout option off its default, built, and
    installed into a prefix other than the configured one; once per run."""
    prefix = WORK / "prefix"
    if not INSTALLED:
        build = WORK / "build"
        shutil.rmtree(build, ignore_errors=True)
        shutil.rmtree(prefix, ignore_errors=True)
        run(["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
             "-DHYST_BUILD_TESTS=OFF", "-DHYST_BUILD_BENCH=OFF", "-DHYST_BUILD_TOOLS=ON",
             "-DHYST_INSTALL=ON", "-DHYST_CODE_BITS=12", f"-DCMAKE_INSTALL_PREFIX={WORK}/unused"])
        run(["cmake", "--build", str(build), "-j2"])
        run(["cmake", "--install", str(build), "--prefix", str(prefix)])
        INSTALLED.append(prefix)
    return prefix


def pkg_config(prefix, *args):
    pcdirs = sorted(str(p.parent) for p in prefix.rglob("hyst.pc"))
    assert len(pcdirs) == 1, f"hyst.pc installed as {pcdirs}"
    env = dict(os.environ, PKG_CONFIG_PATH=pcdirs[0], PKG_CONFIG_LIBDIR=pcdirs[0])
    return run(["pkg-config", *args, "hyst"], env=env).split()


@check("install: hyst.pc, pkg-config --modversion/--cflags --libs hyst")
def _():
    prefix = install_prefix()
    assert pkg_config(prefix, "--modversion") == [version()]
    flags = pkg_config(prefix, "--cflags", "--libs")
    assert "-DHYST_CODE_BITS=12" in flags and "-lhyst" in flags, flags
    for f in flags:
        if f.startswith(("-I", "-L")):
            assert Path(f[2:]).resolve().is_relative_to(prefix), f"{f} is outside the prefix"


@check("install: a C program compiles and links with pkg-config's flags")
def _():
    prefix = install_prefix()
    src = WORK / "app.c"
    src.write_text(PROGRAM)
    cc = os.environ.get("CC", "cc")
    flags = pkg_config(prefix, "--cflags", "--libs")
    warn = ["-std=c99", "-Wall", "-Wextra", "-Wpedantic", "-Wconversion", "-Wshadow", "-Werror"]
    run([cc, *warn, str(src), "-o", str(WORK / "app"), *flags])
    st, ver, y = run([str(WORK / "app")]).split()
    assert int(st) == 0 and ver == version() and 0.58517 < float(y) < 5.5587636, (st, ver, y)
    # without the layout option in Cflags the library refuses the caller
    bare = [f for f in flags if not f.startswith("-D")]
    run([cc, "-std=c99", str(src), "-o", str(WORK / "app_bare"), *bare])
    st = int(run([str(WORK / "app_bare")]).split()[0])
    assert st == -18, f"init without the layout flags returned {st}, not HYST_ERR_LAYOUT (-18)"


@check("install: docs and licence in share/doc/hyst, hyst --version")
def _():
    prefix = install_prefix()
    doc = prefix / "share" / "doc" / "hyst"
    for name in ("LICENSE", "README.md", "api.md", "matlab.md", "figures/compensation.png"):
        assert (doc / name).is_file(), f"{doc / name} not installed"
    assert sorted(p.name for p in (ROOT / "docs").glob("*.md")) == \
        sorted(p.name for p in doc.glob("*.md") if (ROOT / "docs" / p.name).exists())
    assert run([str(prefix / "bin" / "hyst"), "--version"]).strip() == f"hyst {version()}"


def main():
    passed = failed = 0
    for name, fn in RESULTS:
        try:
            fn()
        except Exception as exc:  # noqa: BLE001 - every failure is reported
            failed += 1
            print(f"FAIL {name}: {type(exc).__name__}: {exc}")
        else:
            passed += 1
            print(f"PASS {name}")
    print(f"packaging: {passed} passed, {failed} failed")
    return 1 if failed or not passed else 0


if __name__ == "__main__":
    sys.exit(main())
