// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/store/FrfCapture.h"

#include "core/model/MetadataKeys.h"

#include <cmath>
#include <utility>

namespace axistune::store {

model::Capture frfAsCapture(const dsp::FrequencyResponse& frf)
{
    model::Capture c;
    c.metadata = frf.metadata;
    c.metadata.set(model::meta::kContent, "frf");
    std::vector<model::Channel> ch = {{"f_Hz", frf.freqHz}, {"re", {}}, {"im", {}}, {"mag_dB", {}},
                                      {"phase_deg", {}}, {"coherence", frf.coherence}, {"valid", {}}};
    for (std::size_t i = 0; i < frf.size(); ++i) {
        ch[1].data.push_back(frf.h[i].real());
        ch[2].data.push_back(frf.h[i].imag());
        ch[3].data.push_back(dsp::magnitudeDb(frf.h[i]));
        ch[4].data.push_back(dsp::phaseDeg(frf.h[i]));
        ch[6].data.push_back(i < frf.valid.size() && frf.valid[i] ? 1.0 : 0.0);
    }
    ch[5].data.resize(frf.size(), std::nan(""));
    c.channels = std::move(ch);
    return c;
}

bool isFrfCapture(const model::Capture& capture)
{
    const auto* content = capture.metadata.find(model::meta::kContent);
    return content && *content == "frf";
}

Result<dsp::FrequencyResponse> frfFromCapture(const model::Capture& capture)
{
    const auto* f = capture.channel("f_Hz");
    const auto* re = capture.channel("re");
    const auto* im = capture.channel("im");
    const auto* coh = capture.channel("coherence");
    const auto* valid = capture.channel("valid");
    for (const auto& [ch, name] : {std::pair{f, "f_Hz"}, std::pair{re, "re"}, std::pair{im, "im"}})
        if (!ch)
            return makeError(ErrorCode::BadInput, std::string("stored frequency response: no channel '") + name + "'");
    const std::size_t n = f->data.size();
    if (re->data.size() != n || im->data.size() != n || (coh && coh->data.size() != n) ||
        (valid && valid->data.size() != n))
        return makeError(ErrorCode::BadInput, "stored frequency response: channels of different lengths");
    dsp::FrequencyResponse frf;
    frf.metadata = capture.metadata;
    frf.metadata.erase(model::meta::kContent);
    for (std::size_t i = 0; i < n; ++i)
        frf.push(f->data[i], {re->data[i], im->data[i]}, coh ? coh->data[i] : std::nan(""),
                 valid ? valid->data[i] != 0.0 : true);
    return frf;
}

}  // namespace axistune::store
