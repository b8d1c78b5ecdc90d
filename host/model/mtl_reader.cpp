#include "model/mtl_reader.h"

#include "model/model_paths.h"
#include "model/obj_statements.h"
#include "scene/scene_lexer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <utility>

namespace {

// The file name of a texture statement (map_Kd [options] name): the words after its
// options, joined by single spaces; empty when the statement names none or holds an option
// that is not MTL's (nothing is sampled yet, so such a line costs the model nothing). The
// options are the MTL format's: -blendu, -blendv, -cc, -clamp (on or off), -bm, -texres,
// -imfchan (one value), -mm (two), -o, -s, -t (one to three numbers).
std::string textureFileName(const Statement& statement) {
    const std::vector<std::string_view>& words = statement.words;
    auto isNumber = [](std::string_view word) {
        double value = 0;
        return !word.empty() &&
               scene_lexer::parseNumber(word, value) == scene_lexer::NumberStatus::ok;
    };
    std::size_t i = 1;
    while (i < words.size() && words[i].size() > 1 && words[i][0] == '-') {
        const std::string_view option = words[i];
        std::size_t values = 0, optional = 0;
        if (option == "-blendu" || option == "-blendv" || option == "-cc" || option == "-clamp" ||
            option == "-bm" || option == "-texres" || option == "-imfchan")
            values = 1;
        else if (option == "-mm")
            values = 2;
        else if (option == "-o" || option == "-s" || option == "-t")
            values = 1, optional = 2;
        else
            return {};
        ++i;
        if (i + values > words.size()) return {};
        i += values;
        for (; optional > 0 && i < words.size() && isNumber(words[i]); --optional)
            ++i;
    }
    return i < words.size() ? joinWords(words, i) : std::string();
}

// MTL's illumination model applied to a material read with it: 0 and 1 have no highlight,
// 2 a highlight and no mirror, 3 and above (reflection, glass, Fresnel: all a mirror to
// this renderer) ks as the mirror weight too, as in a scene file.
void applyIllum(Material& material, int illum) {
    if (illum <= 1) material.specular = glm::dvec3(0.0);
    material.mirror = illum >= 3 ? 1.0 : 0.0;
}

} // namespace

// newmtl name -> index into the model's materials, from one MTL file. A line that is wrong
// is a warning, not an error: the material it belongs to falls back to the default one
// (its other lines are not read), a line before any material is left out, and the model
// renders on.
void readMtl(const MtlFile& file, SourceModel& model, std::map<std::string, std::uint32_t>& names) {
    std::optional<std::uint32_t> current;
    std::string currentName;
    bool skipping = false; // the current material's lines are not read (one was wrong)
    bool any = false;
    std::map<std::uint32_t, int> illumOf; // applied at the end: a Ks may follow its illum
    std::set<std::pair<std::string, std::uint32_t>> unrendered; // (what, material), once each
    auto noteUnrendered = [&](const Statement& statement) {
        if (!current) return;
        const std::string_view keyword = statement.words[0];
        auto value = [&](std::size_t i) {
            return i < statement.words.size()
                       ? std::strtod(std::string(statement.words[i]).c_str(), nullptr)
                       : 0.0;
        };
        std::string what;
        if (keyword == "map_Kd") return; // sampled (model/texture_files.h)
        if ((keyword == "d" && statement.words.size() > 1 && value(1) < 1.0) ||
            (keyword == "Tr" && value(1) > 0.0))
            what = "transparency (d, Tr)";
        else if (keyword.starts_with("map_") || keyword == "bump" || keyword == "disp" ||
                 keyword == "decal" || keyword == "refl" || keyword == "norm")
            what = "other maps (bump, map_Ks, ...)";
        if (!what.empty() && unrendered.insert({what, *current}).second) ++model.notRendered[what];
    };
    forEachStatement(*file.text, [&](const Statement& statement) {
        const Place place{file.path, statement.line};
        const std::string_view keyword = statement.words[0];
        if (keyword != "newmtl" && skipping) return;
        noteUnrendered(statement);
        try {
            if (keyword == "newmtl") {
                current.reset();
                skipping = false;
                if (statement.words.size() < 2) {
                    skipping = true; // its lines belong to no material
                    place.fail("newmtl needs a name");
                }
                current = static_cast<std::uint32_t>(model.materials.size());
                currentName = joinWords(statement.words, 1);
                model.materials.push_back(defaultModelMaterial());
                names[currentName] = *current;
                any = true;
            } else if (keyword == "Ke") {
                if (!current) place.fail("Ke before any newmtl");
                Numbers rgb = numbers(place, statement, 1, "Ke", 2);
                if (rgb.size() == 2) place.fail("Ke expects 1 or 3 numbers, got 2");
                if (rgb.size() == 1) rgb = Numbers{{rgb[0], rgb[0], rgb[0]}, 3};
                model.materials[*current].emission =
                    glm::max(glm::dvec3(rgb[0], rgb[1], rgb[2]), glm::dvec3(0.0));
            } else if (keyword == "Kd" || keyword == "Ks") {
                const std::string name(keyword);
                if (!current) place.fail(name + " before any newmtl");
                if (statement.words.size() > 1 &&
                    (statement.words[1] == "spectral" || statement.words[1] == "xyz"))
                    place.fail(name + " " + std::string(statement.words[1]) +
                               " colours are not supported; use r g b");
                Numbers rgb = numbers(place, statement, 1, name, 2);
                if (rgb.size() == 2) place.fail(name + " expects 1 or 3 numbers, got 2");
                if (rgb.size() == 1) rgb = Numbers{{rgb[0], rgb[0], rgb[0]}, 3};
                Material& material = model.materials[*current].phong;
                (keyword == "Kd" ? material.diffuse : material.specular) = clampedColor(rgb, 0);
            } else if (keyword == "Ns") {
                if (!current) place.fail("Ns before any newmtl");
                model.materials[*current].phong.shininess = std::clamp(
                    numbers(place, statement, 1, "Ns")[0], kMinModelShininess, kMaxModelShininess);
            } else if (keyword == "illum") {
                if (!current) place.fail("illum before any newmtl");
                const double illum = numbers(place, statement, 1, "illum")[0];
                if (illum != std::floor(illum) || illum < 0 || illum > 10)
                    place.fail("illum expects an illumination model, a whole number 0 to 10, "
                               "got " +
                               std::string(statement.words[1]));
                illumOf[*current] = static_cast<int>(illum);
            } else if (keyword == "map_Kd" && current) {
                const std::string texture = textureFileName(statement);
                model.materials[*current].diffuseTexture =
                    texture.empty() ? texture : besideFile(file.path, texture);
            }
            // Ka, d, Tr, Ni, other maps: nothing in this renderer's model uses them.
        } catch (const SceneError& error) {
            std::string consequence = "; the line is left out";
            if (current) {
                illumOf.erase(*current);
                model.materials[*current] = defaultModelMaterial();
                skipping = true;
                consequence = "; material '" + currentName + "' is the default one";
            } else if (skipping) {
                consequence = "; the lines up to the next newmtl are left out";
            }
            model.warnings.push_back(sceneLocation(error.file, error.line) +
                                     "warning: " + error.message + consequence);
        }
    });
    for (const auto& [material, illum] : illumOf)
        applyIllum(model.materials[material].phong, illum);
    if (!any) model.warnings.push_back(file.path + ": warning: no materials (newmtl) found");
}
