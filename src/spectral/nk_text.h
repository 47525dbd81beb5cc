#pragma once
// Optical constants from the text files people have (docs/conventions.md, "Inputs"). Every reader
// judges rows like the database reader (tabulated.h) and throws InputError naming file, line and
// problem.
#include <string>

#include "spectral/optical_constants.h"

namespace fl::spectral {

// A table with a header line naming its columns, in any order: the wavelength (`wl`, `lambda`,
// `wavelength`, `λ`, with the unit in the name: `lambda_nm`, `Wavelength (µm)`, `wl [um]`,
// `wavelength, nm` in quotes) or the photon energy in eV (`eV`, `E (eV)`, `energy_eV`: λ = hc / E
// with hc = 1239.841984 eV·nm, rows taken in increasing wavelength), `n` (or `eta`) and optionally
// `k` (or `kappa`); any case, spaces around names ignored. Semicolon-, comma-, tab- or
// whitespace-separated (the header's separator), `#` starts a comment line; a trailing separator
// ("wl,n,k,") ends no column; a lone byte 0xB5 (Windows-1252 µ) in a header is µ. Where a comma
// does not separate columns, "0,5" is a decimal comma; a file mixing decimal commas and points is
// refused; between semicolons, a column mixing them ("300.9;1,4;1,679" keeps one per column).
// A wavelength without a unit is in nm, except refractiveindex.info's `wl`, in µm.
// A new header line starts a new section: refractiveindex.info's CSV download (`wl,n` rows, then
// `wl,k` rows) is two sections. Wavelengths that miss the used range in their unit but would
// overlap it in the other are refused with a message saying so.
OpticalConstants read_nk_table(const std::string& path, const UsedRange& used = {});

// SOPRA's .nk format: a first line "UNIT FIRST LAST INTERVALS" (UNIT 1 = eV, 2 = µm, 3 = cm⁻¹,
// 4 = nm; INTERVALS + 1 evenly spaced points from FIRST to LAST), then n, k pairs (whitespace or
// `;` between values, where a value "0,5" is a decimal comma; any other comma separates values). A
// file whose first line does not start with a number is read as a table.
OpticalConstants read_sopra_nk(const std::string& path, const UsedRange& used = {});

// J.A. Woollam WVASE / CompleteEASE material files (.mat): a name line, a unit line (`nm`, `eV`,
// `um` or `A` for ångström), a type line (`NK`, or `E1E2`: ε1 and ε2, converted to n + ik with
// (n + ik)² = ε1 + iε2; a row count in its place is checked), then rows of the first column's
// quantity and the two values. A MATLAB .mat file is refused as such.
OpticalConstants read_wvase_mat(const std::string& path, const UsedRange& used = {});

// Mitsuba / pbrt spectra: `NAME.eta.spd` and `NAME.k.spd`, each wavelength (nm) and value pairs,
// `#` comments. `path` is either file of the pair; without the k file, k = 0 (a dielectric).
OpticalConstants read_spd_pair(const std::string& path, const UsedRange& used = {});

// By file name: .yml/.yaml a refractiveindex.info page, .nk SOPRA, .mat WVASE, .spd a pair,
// anything else
// (.csv, .txt, .tsv, .dat, ...) a table.
OpticalConstants read_optical_file(const std::string& path, const UsedRange& used = {});

}  // namespace fl::spectral
