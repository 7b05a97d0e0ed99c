/**
 * The head model's node names: the model builder writes them, the page finds the head's parts by them, and the solver
 * finds the lower teeth's colliders by them (colliders take their node's name). One list, so that they cannot drift.
 */
export const HEAD_NODES = Object.freeze({
  /** The skin mesh the solver moves. */
  skin: 'skin',
  /** The eyeballs, placed at their centres (also the names of their pivots). */
  eyes: Object.freeze(['eye-l', 'eye-r'] as const),
  /** The upper teeth, fixed to the head. */
  upperTeeth: 'teeth-upper',
  /** The lower teeth, under the jaw. */
  lowerTeeth: 'teeth-lower',
  tongue: 'tongue',
  /** The node at the jaw hinge that carries the lower teeth and the tongue. */
  jaw: 'jaw',
});
