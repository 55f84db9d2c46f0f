using System.Runtime.CompilerServices;

// Internal like Core; the asmdefs' and the rig's csprojs' names. No player assembly may use it.
[assembly: InternalsVisibleTo("GregoryTerrain.Editor")]
[assembly: InternalsVisibleTo("GregoryTerrain.Core.Tests")]
[assembly: InternalsVisibleTo("GregoryTerrain.Editor.Tests")]
[assembly: InternalsVisibleTo("GregoryTerrain.Tests")]
[assembly: InternalsVisibleTo("gt-cli")]
