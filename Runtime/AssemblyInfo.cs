using System.Runtime.CompilerServices;

// The Unity-side tests (Tests/Runtime, Tests/Editor) check the renderer's per-frame state through
// internal members (uploads, the properties set, the draw material); nothing else sees them.
[assembly: InternalsVisibleTo("GregoryTerrain.Runtime.Tests")]
[assembly: InternalsVisibleTo("GregoryTerrain.Editor.Tests")]
