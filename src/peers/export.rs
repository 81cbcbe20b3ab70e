//! Ready-to-paste parameter snippets for DEM and multibody codes (docs/peers.md §5).
