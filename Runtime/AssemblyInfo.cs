using System.Runtime.CompilerServices;

// The editor tools use the renderer's and the grid asset's internal members (the grid as Core's
// PatchGrid, for the heightmap fit); the Unity-side tests (Tests/Runtime, Tests/Editor) check the
// renderer's per-frame state through internal members (uploads, the properties set, the draw
// material). Nothing else sees them.
[assembly: InternalsVisibleTo("GregoryTerrain.Editor")]
[assembly: InternalsVisibleTo("GregoryTerrain.Runtime.Tests")]
[assembly: InternalsVisibleTo("GregoryTerrain.Editor.Tests")]
