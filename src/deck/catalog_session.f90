!> The session commands of the catalog: DEBUT, POURSUITE, FIN (U4.11.01, U4.11.03, U4.11.02).
!> Part of THE command catalog (deck_catalog_data gathers the parts): keywords, types,
!> cardinality, defaults mirroring Code_Aster's, allowed values and rules, as data.
module catalog_session
    use deck_catalog, only: catalog_t, MANY
    use catalog_common, only: OUI_NON
    implicit none
    private
    public :: describe_session

contains

    subroutine describe_session(c)
        type(catalog_t), intent(inout) :: c
        call c%command('DEBUT', '')
        call describe_session_bookkeeping(c)

        ! POURSUITE (U4.11.03): continues the session of the previous command file; its
        ! keywords steer Code_Aster's database and messages, as DEBUT's do.
        call c%command('POURSUITE', '')
        call describe_session_bookkeeping(c)
        call c%key('FORMAT_HDF', 'TXM', into=OUI_NON, noop=.true.)

        call c%command('FIN', '')
        call c%key('FORMAT_HDF', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('RETASSAGE', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('INFO_RESU', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('PROC0', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('UNITE', 'I', noop=.true.)
    end subroutine describe_session

    !> The bookkeeping keywords DEBUT and POURSUITE share (U4.11.01, U4.11.03): accepted,
    !> no effect in parasol.
    subroutine describe_session_bookkeeping(c)
        type(catalog_t), intent(inout) :: c
        call c%key('CODE', 'ANY', min=0, max=MANY, noop=.true.)
        call c%key('DEBUG', 'ANY', min=0, max=MANY, noop=.true.)
        call c%key('PAR_LOT', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('IMPR_MACRO', 'TXM', into=OUI_NON, noop=.true.)
        call c%key('LANG', 'TXM', noop=.true.)
        call c%key('ERREUR', 'ANY', min=0, max=MANY, noop=.true.)
        call c%key('MEMOIRE', 'ANY', min=0, max=MANY, noop=.true.)
        call c%key('RESERVE_CPU', 'ANY', min=0, max=MANY, noop=.true.)
        call c%key('IGNORE_ALARM', 'TXM', max=MANY, noop=.true.)
        call c%key('INFO', 'I', into='1 2', noop=.true.)
    end subroutine describe_session_bookkeeping

end module catalog_session
