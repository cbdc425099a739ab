from rollspec import contact as contact
from rollspec import spectra as spectra
from rollspec import studies as studies
from rollspec import surfaces as surfaces

__version__: str
