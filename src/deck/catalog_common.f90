!> Named values the catalog modules share: Code_Aster's OUI/NON choice, the ranges of values
!> parasol checks (Code_Aster's val_min/val_max where it has one, parasol's bounds of
!> number_limits where the products formed from a value must stay finite: issue 13) and the
!> component names of the result fields the output commands know.
module catalog_common
    use kinds, only: dp
    implicit none
    private

    character(len=*), parameter, public :: OUI_NON = 'OUI NON'
    real(dp), parameter, public :: ANGLE_MAX = 1.0e30_dp          !< degrees, or a direction vector
    real(dp), parameter, public :: RATIO_MAX = 1.0e10_dp          !< COEF_RIGI_DRZ
    real(dp), parameter, public :: WEIGHT_MAX = 1.0e30_dp         !< RIGI_PARASOL COEF_GROUP
    !> NOM_CMP of TEST_RESU and IMPR_RESU: DEPL, FORC_NODA, REAC_NODA components; SIEF_ELGA
    !> of the discrete springs (N VY VZ); VARI_ELGA of DIS_CHOC (V1 .. V10).
    character(len=*), parameter, public :: RESULT_COMPONENTS = 'DX DY DZ DRX DRY DRZ N VY VZ ' // &
        'V1 V2 V3 V4 V5 V6 V7 V8 V9 V10'
end module catalog_common
