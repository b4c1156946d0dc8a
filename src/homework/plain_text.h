// Markdown with $...$ maths as plain text for widgets that cannot typeset (the app's field labels, choice
// buttons and Check's verdicts): the dollars and braces go, common commands become their Unicode symbols
// (\rho -> ρ, \le -> ≤, \sqrt -> √, \operatorname{diag} -> diag), so "$\rho_i F_{ij}$" reads "ρ_i F_ij".
#pragma once

#include <string>

namespace rt::homework {

std::string plainText(const std::string& markdown);

}  // namespace rt::homework
