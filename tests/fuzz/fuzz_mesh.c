/* fuzz_mesh.c: libFuzzer harness for the mesh reader (render/mesh/mesh_import.c over
 * assimp). assimp picks its reader by the file's extension, so the input's first byte
 * picks it (its value mod 4: '0' PLY, '1' OBJ, '2' STL, '3' OFF) and the rest is the file. */
#include "fuzz.h"
#include "mesh_import.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	static const char *const names[4] = { "mesh.ply", "mesh.obj", "mesh.stl", "mesh.off" };
	if (size == 0)
		return 0;
	const char *path = fuzz_file(names[data[0] % 4], data + 1, size - 1);
	struct mesh_data m;
	char err[512];
	mesh_import(path, &m, err, sizeof err);
	mesh_import_free(&m);
	return 0;
}
