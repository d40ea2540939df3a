package = "arclen-svg"
version = "scm-1"
source = { url = "git+file://." }
description = {
  summary = "SVG documents for arclen: the reader arclen.svg drives (over expat)",
  detailed = [[The C module arclen.svgdoc, a streaming SVG document reader over
  libexpat: require "arclen.svg" (in the rock arclen) needs it.]],
  license = "MIT",
}
dependencies = { "lua >= 5.1", "arclen" }
external_dependencies = { EXPAT = { header = "expat.h" },
  platforms = { unix = { ZLIB = { header = "zlib.h" } } } }
build = {
  type = "builtin",
  modules = {
    ["arclen.svgdoc"] = {
      sources = {
        "src/lua/svgdoc.c",
        "src/lua/svgdoc_gzip.c",
        "src/lua/subpaths.c",
        "src/svgdoc/attrs.c",
        "src/svgdoc/gzip.c",
        "src/svgdoc/idbloom.c",
        "src/svgdoc/memory.c",
        "src/svgdoc/reader.c",
        "src/svgdoc/shapes.c",
        "src/baseline/baseline.c",
        "src/baseline/gravesen.c",
        "src/conic/conic.c",
        "src/conic/conic_arc.c",
        "src/conic/conic_length.c",
        "src/curve/cubic.c",
        "src/curve/legendre.c",
        "src/curve/options.c",
        "src/elliptic/carlson.c",
        "src/elliptic/elliptic.c",
        "src/elliptic/elliptic3d.c",
        "src/elliptic/elliptic_far.c",
        "src/elliptic/product.c",
        "src/fit/lenfit.c",
        "src/fit/lenfit_error.c",
        "src/fit/lenfit_eval.c",
        "src/gauss/api.c",
        "src/gauss/batch.c",
        "src/gauss/bound.c",
        "src/gauss/branch.c",
        "src/gauss/ellipse_table.c",
        "src/gauss/gauss_tables.c",
        "src/gauss/integrator.c",
        "src/gauss/length.c",
        "src/gauss/speed_sum.c",
        "src/gauss/time.c",
        "src/metapost/metapost.c",
        "src/methods/methods.c",
        "src/roots/roots.c",
        "src/roots/roots3d.c",
        "src/segment/conic_seg.c",
        "src/segment/invert.c",
        "src/segment/line.c",
        "src/segment/quad.c",
        "src/segment/segment.c",
        "src/svg/decimal.c",
        "src/svg/decimal_exact.c",
        "src/svg/decimal_print.c",
        "src/svg/pathdata.c",
        "src/svg/pathdata_message.c",
      },
      defines = { "_POSIX_C_SOURCE=200809L" },
      libraries = { "expat" },
      incdirs = { "src", "$(EXPAT_INCDIR)" },
      libdirs = { "$(EXPAT_LIBDIR)" },
    },
  },
  platforms = {
    unix = {
      modules = {
        ["arclen.svgdoc"] = { libraries = { "expat", "z", "m" },
          defines = { "_POSIX_C_SOURCE=200809L", "ARCLEN_HAVE_ZLIB" },
          incdirs = { "src", "$(EXPAT_INCDIR)", "$(ZLIB_INCDIR)" },
          libdirs = { "$(EXPAT_LIBDIR)", "$(ZLIB_LIBDIR)" } },
      },
    },
  },
}
