!> The catalog of the commands that make and transform fields: CREA_CHAMP, CALC_CHAMP,
!> POST_CHAMP, CREA_RESU (doc/architecture.md, "Fields and results"). Part of THE command
!> catalog (deck_catalog_data gathers the parts): keywords, types, cardinality, defaults
!> mirroring Code_Aster's (code_aster/Cata/Commands/<command>.py and its U4 documents),
!> allowed values and rules, as data.
module catalog_fields
    implicit none
    private

    !> The field names of Code_Aster's results (code_aster/Cata/Commons/c_nom_cham_into.py,
    !> C_NOM_CHAM_INTO): what NOM_CHAM accepts in TEST_RESU, IMPR_RESU, CREA_CHAMP EXTR...
    !> A name parasol does not compute is refused when the command runs, naming what the
    !> result holds.
    character(len=*), parameter, public :: NOM_CHAM_NAMES = &
        'EFGE_ELGA EFGE_ELNO EGRU_ELNO EFGE_NOEU SIEF_ELGA SIEF_ELNO SIMY_ELGA SIEF_NOEU ' // &
        'SIGM_ELGA SIGM_ELNO SIGM_NOEU SIPM_ELNO SIPO_ELNO SIPO_NOEU SIRO_ELEM STRX_ELGA ' // &
        'DEGE_ELGA DEGE_ELNO DEGE_NOEU EPFD_ELGA EPFD_ELNO EPFD_NOEU EPFP_ELGA EPFP_ELNO ' // &
        'EPFP_NOEU EPME_ELGA EPME_ELNO EPME_NOEU EPMG_ELGA EPMG_ELNO EPMG_NOEU EPSG_ELGA ' // &
        'EPSG_ELNO EPSG_NOEU EPSI_ELGA EPSI_ELNO EPSI_NOEU EPSP_ELGA EPSP_ELNO EPSP_NOEU ' // &
        'EPVC_ELGA EPVC_ELNO EPVC_NOEU EPSL_ELGA EPSL_ELNO EPSL_NOEU DISS_ELEM DISS_ELGA ' // &
        'DISS_ELNO DISS_NOEU ECIN_ELEM ENEL_ELEM ENEL_ELGA ENEL_ELNO ENEL_NOEU ENTR_ELEM ' // &
        'EPOT_ELEM ETOT_ELEM ETOT_ELGA ETOT_ELNO ETOT_NOEU DERA_ELGA DERA_ELNO DERA_NOEU ' // &
        'ENDO_ELGA ENDO_ELNO ENDO_NOEU EPEQ_ELGA EPEQ_ELNO EPEQ_NOEU EPGQ_ELGA EPGQ_ELNO ' // &
        'EPGQ_NOEU EPMQ_ELGA EPMQ_ELNO EPMQ_NOEU INDL_ELGA PDIL_ELGA SIEQ_ELGA SIEQ_ELNO ' // &
        'SIEQ_NOEU VARC_ELGA VARC_ELNO VARC_NOEU VARI_ELNO VARI_NOEU FLHN_ELGA TEMP_ELGA ' // &
        'FLUX_ELGA FLUX_ELNO FLUX_NOEU GRAT_ELGA GRAT_ELNO GRAT_NOEU HYDR_ELGA HYDR_ELNO ' // &
        'HYDR_NOEU SOUR_ELGA ETHE_ELEM HHO_TEMP DIFF_ELGA DIFF_ELNO DIFF_NOEU HYGR_ELGA ' // &
        'HYGR_ELNO HYGR_NOEU PRAC_ELNO PRAC_NOEU PRME_ELNO INTE_ELNO INTE_NOEU FORC_NODA ' // &
        'REAC_NODA SIZ1_NOEU ERZ1_ELEM SIZ2_NOEU ERZ2_ELEM ERME_ELEM ERME_ELNO ERME_NOEU ' // &
        'QIRE_ELEM QIRE_ELNO QIRE_NOEU QIZ1_ELEM QIZ2_ELEM SING_ELEM SING_ELNO ERTH_ELEM ' // &
        'ERTH_ELNO ERTH_NOEU DURT_ELNO DURT_NOEU META_ELNO META_NOEU ACCE ACCE_ABSOLU DEPL ' // &
        'DEPL_ABSOLU HHO_DEPL TEMP VITE HHO_VITE CONT_NOEU CONT_ELEM VARI_ELGA VITE_ABSOLU ' // &
        'DEPL_ELGA SECH MATE_ELGA MATE_ELEM COMPORTEMENT COMPORTHER DEPL_VIBR DIVU EPSA_ELNO ' // &
        'EPSA_NOEU FERR_ELEM MARG_ELEM FSUR_2D FSUR_3D FVOL_2D FVOL_3D COEF_H T_EXT IRRA ' // &
        'MODE_FLAMB MODE_STAB NEUT PRES PRES_NOEU PTOT RESI_NOEU RESI_RELA_NOEU SISE_ELNO ' // &
        'VITE_VENT'

    public :: describe_fields

contains

    !> The field commands (filled in as they are built).
    subroutine describe_fields(c)
        use deck_catalog, only: catalog_t
        type(catalog_t), intent(inout) :: c
        if (.false.) c%ncmd = c%ncmd
    end subroutine describe_fields

end module catalog_fields
