import { DirectionalLight, HemisphereLight, type Scene, Vector3 } from 'three';
import { LIGHT_DEFAULTS, LIGHT_RANGES, type LightOptions } from './view-options';
import { checkOptions } from '../core/check';

const DEGREES = Math.PI / 180;
/** How far the key light sits from the head's centre, in metres (a directional light: only its direction counts). */
const KEY_DISTANCE = 1.3;

/** The view's adjustable lights: a hemisphere fill and a key light that turns about the head's centre. */
export class ViewLights {
  readonly ambient: HemisphereLight;
  readonly key: DirectionalLight;
  private readonly light: Required<LightOptions> = { ...LIGHT_DEFAULTS };
  /** Where the key light aims and turns around: the head's centre once a head is shown. */
  private readonly centre = new Vector3();

  constructor(scene: Scene) {
    this.ambient = new HemisphereLight(0xf4f1ec, 0x3a302c);
    this.key = new DirectionalLight();
    scene.add(this.ambient, this.key, this.key.target);
    this.apply();
  }

  /** Changes some light options; throws, changing nothing, on an unknown option or a value of the wrong type or range. */
  set(partial: Partial<LightOptions>): void {
    Object.assign(this.light, checkOptions<LightOptions>('setLight', partial, LIGHT_DEFAULTS, { ranges: LIGHT_RANGES }));
    this.apply();
  }

  /** A copy of the current light options. */
  options(): LightOptions {
    return { ...this.light };
  }

  /** Aims the key light at a new head centre. */
  aimAt(centre: Vector3): void {
    this.centre.copy(centre);
    this.apply();
  }

  private apply(): void {
    const l = this.light;
    this.ambient.intensity = l.ambientIntensity;
    this.key.intensity = l.keyIntensity;
    this.key.color.set(l.keyColor);
    const azimuth = l.keyAzimuth * DEGREES;
    const elevation = l.keyElevation * DEGREES;
    const horizontal = KEY_DISTANCE * Math.cos(elevation);
    this.key.position.set(
      this.centre.x + horizontal * Math.sin(azimuth),
      this.centre.y + KEY_DISTANCE * Math.sin(elevation),
      this.centre.z + horizontal * Math.cos(azimuth),
    );
    this.key.target.position.copy(this.centre);
  }
}
