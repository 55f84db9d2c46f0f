using System.Runtime.CompilerServices;

// The authoring code (fitting, G1 building, brushes, heightmap readers) is internal like Core's; these
// assemblies use it. The names are the asmdefs' (Unity: the editor tools and the Editor-only test
// assemblies) and the csprojs' (the off-Unity rig: the dotnet test project and gt-cli). No player
// assembly may reference this one: Unity compiles it for the Editor only.
[assembly: InternalsVisibleTo("GregoryTerrain.Editor")]
[assembly: InternalsVisibleTo("GregoryTerrain.Core.Tests")]
[assembly: InternalsVisibleTo("GregoryTerrain.Editor.Tests")]
[assembly: InternalsVisibleTo("GregoryTerrain.Tests")]
[assembly: InternalsVisibleTo("gt-cli")]
