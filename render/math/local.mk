# render/math/local.mk: the vector types, headers only.
MATH_INCLUDES = -I$(srcdir)/%D%
noinst_HEADERS = %D%/vec.h %D%/rounding.h %D%/v4d.h %D%/v4f.h %D%/affine.h
