!> The composition root: the one place that knows every layer's command handlers and
!> registers them with the deck dispatcher (doc/architecture.md). A command of the catalog
!> without a registered handler stops the run with "COMMAND is not implemented yet".
module command_registration
    use run_context, only: run_context_t
    use session_commands, only: run_debut, run_poursuite, run_fin, run_debug, &
        run_defi_fichier, run_detruire
    use defi_pres_ec8_command, only: run_defi_pres_ec8
    use function_commands, only: run_defi_constante, run_defi_fonction, run_formule, &
        run_defi_list_reel
    use test_resu_command, only: run_test_resu
    use impr_resu_command, only: run_impr_resu
    use crea_champ_command, only: run_crea_champ
    use calc_champ_command, only: run_calc_champ
    use crea_resu_command, only: run_crea_resu
    use post_champ_command, only: run_post_champ
    use modi_repere_command, only: run_modi_repere
    use lire_champ_command, only: run_lire_champ
    use proj_champ_command, only: run_proj_champ
    use calc_erreur_command, only: run_calc_erreur
    use mesh_commands, only: run_lire_maillage, run_pre_gibi
    use mesh_group_commands, only: run_defi_group
    use mesh_modify_commands, only: run_modi_maillage, set_field_support_resolver
    use field_support, only: mesh_of_support
    use relation_proj, only: set_projection_resolver
    use projection_links, only: links_of_projection
    use mesh_create_commands, only: run_crea_maillage
    use model_commands, only: run_affe_modele
    use material_commands, only: run_defi_materiau, run_affe_materiau
    use composite_command, only: run_defi_composite
    use cara_elem_commands, only: run_affe_cara_elem
    use load_commands, only: run_affe_char_meca, run_affe_char_meca_f, run_affe_char_cine, &
        run_affe_char_cine_f
    use analysis_commands, only: run_stat_non_line, run_meca_statique
    use time_stepping, only: run_defi_list_inst
    use crea_table_command, only: run_crea_table
    use calc_table_command, only: run_calc_table
    use lire_table_command, only: run_lire_table
    use recu_fonction_command, only: run_recu_fonction
    use calc_fonction_command, only: run_calc_fonction
    use post_releve_command, only: run_post_releve_t
    use macr_lign_coupe_command, only: run_macr_lign_coupe
    use post_elem_command, only: run_post_elem
    use test_fonction_command, only: run_test_fonction
    use impr_fonction_command, only: run_impr_fonction
    use test_table_command, only: run_test_table
    use impr_table_command, only: run_impr_table
    use table_methods, only: register_table_methods
    implicit none
    private
    public :: register_commands

contains

    !> Registers every available handler in ctx. Function commands are side-effect free and
    !> also run in the check pass (at_check), so `parasol --check` reports their errors.
    subroutine register_commands(ctx)
        type(run_context_t), intent(inout) :: ctx
        ! DEBUT and POURSUITE decide which names a command file sees: the check pass too.
        call ctx%register('DEBUT', run_debut, at_check=.true.)
        call ctx%register('POURSUITE', run_poursuite, at_check=.true.)
        call ctx%register('FIN', run_fin)
        call ctx%register('DEBUG', run_debug)
        call ctx%register('MAJ_CATA', run_debug)     ! no effect either (field, zzzz230a)
        call ctx%register('DEFI_FICHIER', run_defi_fichier)
        ! DETRUIRE forgets names: the check pass too, so that it sees the names the run sees
        call ctx%register('DETRUIRE', run_detruire, at_check=.true.)
        call ctx%register('DEFI_CONSTANTE', run_defi_constante, at_check=.true.)
        call ctx%register('DEFI_FONCTION', run_defi_fonction, at_check=.true.)
        call ctx%register('FORMULE', run_formule, at_check=.true.)
        call ctx%register('DEFI_LIST_REEL', run_defi_list_reel, at_check=.true.)
        call ctx%register('DEFI_PRES_EC8', run_defi_pres_ec8, at_check=.true.)
        call ctx%register('TEST_RESU', run_test_resu)
        call ctx%register('IMPR_RESU', run_impr_resu)
        call ctx%register('CREA_CHAMP', run_crea_champ)
        call ctx%register('CALC_CHAMP', run_calc_champ, reuse=.true.)
        call ctx%register('CREA_RESU', run_crea_resu, reuse=.true.)
        call ctx%register('POST_CHAMP', run_post_champ)
        call ctx%register('MODI_REPERE', run_modi_repere, reuse=.true.)
        call ctx%register('LIRE_CHAMP', run_lire_champ)
        call ctx%register('PROJ_CHAMP', run_proj_champ, reuse=.true.)
        call ctx%register('CALC_ERREUR', run_calc_erreur, reuse=.true.)
        call ctx%register('LIRE_MAILLAGE', run_lire_maillage)
        call ctx%register('PRE_GIBI', run_pre_gibi)
        call ctx%register('DEFI_GROUP', run_defi_group, reuse=.true.)
        call ctx%register('MODI_MAILLAGE', run_modi_maillage, reuse=.true.)
        call set_field_support_resolver(mesh_of_support)   ! DEFORME's DEPL on a model, a result
        call ctx%register('CREA_MAILLAGE', run_crea_maillage)
        call ctx%register('AFFE_MODELE', run_affe_modele)
        call ctx%register('DEFI_MATERIAU', run_defi_materiau, at_check=.true.)
        call ctx%register('DEFI_COMPOSITE', run_defi_composite, at_check=.true.)
        call ctx%register('AFFE_MATERIAU', run_affe_materiau)
        call ctx%register('AFFE_CARA_ELEM', run_affe_cara_elem)
        call ctx%register('AFFE_CHAR_MECA', run_affe_char_meca)
        call set_projection_resolver(links_of_projection)   ! LIAISON_PROJ's PROJ_CHAMP links
        call ctx%register('AFFE_CHAR_MECA_F', run_affe_char_meca_f)
        call ctx%register('AFFE_CHAR_CINE', run_affe_char_cine)
        call ctx%register('AFFE_CHAR_CINE_F', run_affe_char_cine_f)
        call ctx%register('MECA_STATIQUE', run_meca_statique)
        call ctx%register('STAT_NON_LINE', run_stat_non_line, reuse=.true.)
        call ctx%register('DEFI_LIST_INST', run_defi_list_inst)
        ! tables (issue 20)
        call ctx%register('CREA_TABLE', run_crea_table)
        call ctx%register('CALC_TABLE', run_calc_table)
        call ctx%register('LIRE_TABLE', run_lire_table)
        call ctx%register('RECU_FONCTION', run_recu_fonction)
        call ctx%register('CALC_FONCTION', run_calc_fonction)
        call ctx%register('POST_RELEVE_T', run_post_releve_t)
        call ctx%register('MACR_LIGN_COUPE', run_macr_lign_coupe)
        call ctx%register('POST_ELEM', run_post_elem)
        call ctx%register('TEST_FONCTION', run_test_fonction)
        call ctx%register('IMPR_FONCTION', run_impr_fonction)
        call ctx%register('TEST_TABLE', run_test_table)
        call ctx%register('IMPR_TABLE', run_impr_table)
        ! the Python side of tables: TAB['DX', 1], TAB.EXTR_TABLE(), tab.DY[0] (table_methods)
        call register_table_methods(ctx)
    end subroutine register_commands

end module command_registration
