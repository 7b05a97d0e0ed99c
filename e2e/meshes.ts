/** An OBJ of `n` by `n` quads on a sphere of radius 0.1 m about (0, 0.7, 0): head-sized, but with no eyes or mouth. */
export function sphereObj(n: number): string {
  const lines: string[] = [];
  for (let j = 0; j <= n; j++) {
    for (let i = 0; i <= n; i++) {
      const t = (Math.PI * j) / n;
      const p = (2 * Math.PI * i) / n;
      lines.push(`v ${0.1 * Math.sin(t) * Math.sin(p)} ${0.7 + 0.1 * Math.cos(t)} ${0.1 * Math.sin(t) * Math.cos(p)}`);
    }
  }
  for (let j = 0; j < n; j++)
    for (let i = 0; i < n; i++)
      lines.push(`f ${j * (n + 1) + i + 1} ${(j + 1) * (n + 1) + i + 1} ${(j + 1) * (n + 1) + i + 2} ${j * (n + 1) + i + 2}`);
  return lines.join('\n');
}
