/** Candidate Chromium locations, in order. */
export declare const CHROMIUM_CANDIDATES: string[];
/** Where the Chromium for browser tests is: $CHROMIUM_PATH if set, else the first one found. */
export declare function chromiumPath(): string;
