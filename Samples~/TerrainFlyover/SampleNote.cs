using UnityEngine;

namespace GregoryTerrain.Samples.TerrainFlyover
{
    /// <summary>Sample: a note for whoever opens the scene, read in the Inspector. It does nothing at run time.</summary>
    [AddComponentMenu("Gregory Terrain/Samples/Sample Note")]
    public sealed class SampleNote : MonoBehaviour
    {
        [TextArea(3, 20)]
        [SerializeField] string note = "";

        /// <summary>The note's text.</summary>
        public string Note => note;
    }
}
