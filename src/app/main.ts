import { loadHeadModel } from '../render/head-model';
import { HeadView } from '../render/head-view';

const RESOLUTIONS = ['low', 'medium', 'high'] as const;
type Resolution = (typeof RESOLUTIONS)[number];

/** `?resolution=low|medium|high` picks the head; medium is the default. */
function requestedResolution(): Resolution {
  const r = new URLSearchParams(location.search).get('resolution');
  return RESOLUTIONS.includes(r as Resolution) ? (r as Resolution) : 'medium';
}

const modelStatus = document.getElementById('status-model')!;
const isolationStatus = document.getElementById('status-isolation')!;
isolationStatus.textContent = crossOriginIsolated ? 'cross-origin isolated' : 'not cross-origin isolated';
isolationStatus.dataset.isolated = String(crossOriginIsolated);

const view = new HeadView(document.getElementById('viewport')!);
view.start();

const resolution = requestedResolution();
const url = `${import.meta.env.BASE_URL}models/head-${resolution}.glb`;
try {
  const head = await loadHeadModel(url);
  view.setHead(head);
  const l = head.info.level;
  modelStatus.textContent = `${l.name} head: ${l.skinVertices.toLocaleString('en-US')} vertices, ${l.triangles.toLocaleString('en-US')} triangles`;
  document.documentElement.dataset.state = 'ready';
} catch (error) {
  modelStatus.textContent = `The head could not be loaded: ${(error as Error).message}`;
  modelStatus.className = 'error';
  document.documentElement.dataset.state = 'error';
  console.error(error);
}
