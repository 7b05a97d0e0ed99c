import { describeHighSettles } from './fixtures/high-settles';

// The brows', lids', head's and eyes' Action Units on the high head not settled elsewhere (AU4, AU6, AU9 and AU1 with
// AU2 in tests/wrinkles-high-no-crumpling.test.ts, AU43 and AU46 in tests/expressions-settle-high-lids.test.ts; AU45
// is AU43's muscles, frame for frame). The head's turns pull the neck's skin; the eyes' turns carry the lids.
describeHighSettles('the upper face, the head and the eyes', [
  'AU1',
  'AU2',
  'AU5',
  'AU7',
  'AU38',
  'AU39',
  'AU41',
  'AU42',
  'AU44',
  'AU51',
  'AU52',
  'AU53',
  'AU54',
  'AU55',
  'AU56',
  'AU57',
  'AU58',
  'AU61',
  'AU62',
  'AU63',
  'AU64',
  'AU65',
  'AU66',
]);
