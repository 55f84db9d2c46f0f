namespace GregoryTerrain
{
    /// <summary>
    /// Where <see cref="GregoryTerrainRenderer"/> evaluates the terrain's tessellated vertices
    /// (Documentation~/index.md, "Vertex evaluation: domain stage or compute cache").
    /// </summary>
    public enum VertexEvaluation
    {
        /// <summary>
        /// The domain stage evaluates every vertex of every pass and camera (patch lookup, Gregory
        /// evaluation, noise); factors are fractional and follow each camera. Works on every GPU with
        /// a tessellator.
        /// </summary>
        DomainStage = 0,

        /// <summary>
        /// A compute pre-pass (<c>Shaders/Cache/TerrainCache.compute</c>) evaluates each vertex once into a
        /// buffer, in frames where the LOD camera, the range or a setting changed; the domain stage
        /// only reads it (material keyword <c>GT_VERTEX_CACHE</c>). Integer factors, from the LOD
        /// camera for every camera and pass. Needs compute shaders; the renderer falls back to
        /// <see cref="DomainStage"/> (with one warning) where it cannot run.
        /// </summary>
        ComputeCache = 1,
    }
}
