import { type Material, type Object3D, Texture } from 'three';

/** Frees the geometries, materials and textures of every object under `root`, each once. */
export function disposeTree(root: Object3D): void {
  const materials = new Set<Material>();
  root.traverse((o) => {
    // Meshes, lines and points: whatever draws a geometry.
    if (!('geometry' in o)) return;
    const withGeometry = o as Object3D & { geometry?: { dispose(): void }; material?: Material | Material[] };
    withGeometry.geometry?.dispose();
    const m = withGeometry.material;
    if (m) for (const material of Array.isArray(m) ? m : [m]) materials.add(material);
  });
  for (const material of materials) {
    for (const value of Object.values(material)) if (value instanceof Texture) value.dispose();
    material.dispose();
  }
}
