package = "arclen"
version = "scm-1"
source = { url = "git+file://." }
description = {
  summary = "Arc length of cubic Bezier curves: exact, elliptic, MetaPost-faithful",
  detailed = [[A C99 core bound for Lua: error-controlled length and its inverse,
  Carlson elliptic integrals, MetaPost arclength/arctime bit for bit, Gravesen
  subdivision, Walter & Fournier length fits, Floater conic approximations.]],
  license = "MIT",
}
dependencies = { "lua >= 5.1" }
build = {
  type = "builtin",
  modules = {
    arclen = {
      sources = {
        "src/baseline.c",
        "src/batch.c",
        "src/branch.c",
        "src/carlson.c",
        "src/conic.c",
        "src/conic_arc.c",
        "src/conic_length.c",
        "src/cubic.c",
        "src/ellipse_table.c",
        "src/elliptic.c",
        "src/elliptic3d.c",
        "src/elliptic_far.c",
        "src/gauss_bound.c",
        "src/gauss_tables.c",
        "src/gravesen.c",
        "src/legendre.c",
        "src/lenfit.c",
        "src/lenfit_error.c",
        "src/lenfit_eval.c",
        "src/lua_arclen.c",
        "src/lua_batch.c",
        "src/lua_conic.c",
        "src/lua_elliptic.c",
        "src/lua_fit.c",
        "src/lua_henkel.c",
        "src/lua_path.c",
        "src/metapost.c",
        "src/methods.c",
        "src/quadrature.c",
        "src/roots.c",
        "src/speed_sum.c",
      },
      defines = { "_POSIX_C_SOURCE=200809L" },
      libraries = { "m" },
      incdirs = { "src" },
    },
    ["arclen.cli"] = "lua/arclen/cli.lua",
    ["arclen.mplib"] = "lua/arclen/mplib.lua",
    ["arclen.path"] = "lua/arclen/path.lua",
    ["arclen.repro.conicplot"] = "lua/arclen/repro/conicplot.lua",
    ["arclen.repro.fitstats"] = "lua/arclen/repro/fitstats.lua",
    ["arclen.repro.henkel"] = "lua/arclen/repro/henkel.lua",
    ["arclen.repro.plot"] = "lua/arclen/repro/plot.lua",
    ["arclen.repro.svgplot"] = "lua/arclen/repro/svgplot.lua",
    ["arclen.svgpath"] = "lua/arclen/svgpath.lua",
  },
  install = { bin = { arclen = "bin/arclen" } },
}
