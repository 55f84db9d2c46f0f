using System.Runtime.CompilerServices;

// The editor tools use the renderer's and the grid asset's internal members (the grid as Core's
// PatchGrid, for the heightmap fit).
[assembly: InternalsVisibleTo("GregoryTerrain.Editor")]
